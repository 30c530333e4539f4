#include "rft/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "rft/input_error.h"

namespace touchdown {

namespace {

std::string OsReason(int error) { return std::generic_category().message(error); }

// Why open() failed, in the words a user needs.
std::string OpenFailure(int error, const std::string& what) {
  switch (error) {
    case ENOENT: return what + " not found";
    case ENOTDIR: return what + " not found (a part of the path is not a directory)";
    case ELOOP: return "symbolic link loop (too many levels of symbolic links)";
    case EACCES:
    case EPERM: return "permission denied";
    default: return "cannot open: " + OsReason(error);
  }
}

std::string NotRegular(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

// An open descriptor of a readable regular file, closed on destruction.
class InputFd {
 public:
  InputFd(const std::string& path, const std::string& what) {
    if (path.empty()) throw MakeInputError("", "", "empty " + what + " path");
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused just below.
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd_ < 0) {
      const int error = errno;
      throw InputFileError(MakeInputError(path, "", OpenFailure(error, what)).what(), error);
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
      const int error = errno;
      ::close(fd_);
      throw MakeInputError(path, "", "cannot read: " + OsReason(error));
    }
    if (!S_ISREG(st.st_mode)) {
      ::close(fd_);
      throw MakeInputError(path, "", NotRegular(st.st_mode));
    }
  }
  ~InputFd() { ::close(fd_); }
  InputFd(const InputFd&) = delete;
  InputFd& operator=(const InputFd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_ = -1;
};

}  // namespace

void RequireReadableFile(const std::string& path, const std::string& what) { InputFd file(path, what); }

std::string ReadInputFile(const std::string& path, const std::string& what) {
  const InputFd file(path, what);
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(file.get(), buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw MakeInputError(path, "", "cannot read: " + OsReason(errno));
    }
    bytes.append(buffer, static_cast<size_t>(n));
  }
  return bytes;
}

bool IsValidUtf8(std::string_view text) {
  size_t i = 0;
  const size_t n = text.size();
  auto continuation = [&](size_t k) { return k < n && (static_cast<unsigned char>(text[k]) & 0xC0) == 0x80; };
  while (i < n) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    int length = 0;
    unsigned int code = 0;
    if (c >= 0xC2 && c <= 0xDF) {
      length = 2;
      code = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
      length = 3;
      code = c & 0x0F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      length = 4;
      code = c & 0x07;
    } else {
      return false;  // a stray continuation byte, an overlong lead (C0, C1) or F5..FF
    }
    for (int k = 1; k < length; ++k) {
      if (!continuation(i + k)) return false;
      code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    }
    if ((length == 3 && code < 0x800) || (length == 4 && (code < 0x10000 || code > 0x10FFFF)) ||
        (code >= 0xD800 && code <= 0xDFFF))
      return false;
    i += length;
  }
  return true;
}

}  // namespace touchdown
