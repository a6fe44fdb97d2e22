#include "core/util/error_line.h"

#include <unistd.h>

namespace mpmice::core {

namespace {
int g_copyFd = -1;

void writeLine(int fd, const std::string& line) {
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd, line.data() + done, line.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
}
}  // namespace

void copyErrorLinesTo(int fd) { g_copyFd = fd; }

void writeErrorLine(const std::string& program, const std::string& message) {
  const std::string line = program + ": error: " + message + "\n";
  writeLine(STDERR_FILENO, line);
  if (g_copyFd >= 0) writeLine(g_copyFd, line);
}

}  // namespace mpmice::core
