#include "core/io/log_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <unistd.h>

#include "core/io/run_metadata.h"
#include "core/util/error_line.h"
#include "core/version.h"

namespace mpmice::core {

namespace {

void writeAll(int fd, const char* data, std::size_t n) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t w = ::write(fd, data + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return;
    done += static_cast<std::size_t>(w);
  }
}

/// Passes everything to the stream's own buffer and appends it to the log.
class TeeBuffer final : public std::streambuf {
 public:
  TeeBuffer(std::streambuf* terminal, int fd) : terminal_(terminal), fd_(fd) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    writeAll(fd_, &ch, 1);
    return terminal_->sputc(ch);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    writeAll(fd_, s, static_cast<std::size_t>(n));
    return terminal_->sputn(s, n);
  }
  int sync() override { return terminal_->pubsync(); }

 private:
  std::streambuf* terminal_;
  int fd_;
};

}  // namespace

std::string logFilePath(const Scene& scene, const std::string& program) {
  return (std::filesystem::path(scene.output.directory) / ("log." + program)).string();
}

LogFile::LogFile(const std::string& path, const std::string& program, const Scene& scene, const std::string& launchedBy)
    : path_(path) {
  std::error_code ec;
  const auto dir = std::filesystem::path(path).parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot append to the log file " + path + ": " + std::strerror(errno));
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const std::string who = launchedBy.empty() ? versionLine(program) : program + " (launched by " + versionLine(launchedBy) + ")";
  write("==== " + who + ": scene '" + scene.name + "' (" + scene.file + "), started " + utcNow() +
        ", pid " + std::to_string(getpid()) + " on " + host + " ====\n");
}

LogFile::~LogFile() {
  if (outOld_) {
    std::cout.flush();
    std::cout.rdbuf(outOld_);
  }
  if (errOld_) {
    std::cerr.flush();
    std::cerr.rdbuf(errOld_);
  }
  copyErrorLinesTo(-1);
  if (fd_ >= 0) ::close(fd_);
}

void LogFile::write(std::string_view text) const { writeAll(fd_, text.data(), text.size()); }

void LogFile::tee() {
  std::cout.flush();
  std::cerr.flush();
  outTee_ = std::make_unique<TeeBuffer>(std::cout.rdbuf(), fd_);
  errTee_ = std::make_unique<TeeBuffer>(std::cerr.rdbuf(), fd_);
  outOld_ = std::cout.rdbuf(outTee_.get());
  errOld_ = std::cerr.rdbuf(errTee_.get());
  copyErrorLinesTo(fd_);
}

std::unique_ptr<LogFile> LogFile::teeProgramOutput(const Comm& comm, const Scene& scene, const std::string& program) {
  if (!scene.output.enabled || !comm.root()) return nullptr;
  auto log = std::make_unique<LogFile>(logFilePath(scene, program), program, scene);
  log->tee();
  return log;
}

}  // namespace mpmice::core
