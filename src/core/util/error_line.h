#pragma once
/// @brief One error line to stderr in one write: "<program>: error: <message>\n".
///
/// The programs of an MPMD launch share the terminal (and `coupler run`'s pipe); a line written
/// in pieces interleaves with the peer's output. A single write of up to PIPE_BUF bytes (4096)
/// to a pipe is atomic.
#include <string>

namespace mpmice::core {

void writeErrorLine(const std::string& program, const std::string& message);
/// Error lines also go to `fd` (the program's log file, core/io/log_file.h); -1: stderr only.
void copyErrorLinesTo(int fd);

}  // namespace mpmice::core
