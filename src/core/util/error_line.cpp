#include "core/util/error_line.h"

#include <unistd.h>

namespace mpmice::core {

void writeErrorLine(const std::string& program, const std::string& message) {
  const std::string line = program + ": error: " + message + "\n";
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(STDERR_FILENO, line.data() + done, line.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace mpmice::core
