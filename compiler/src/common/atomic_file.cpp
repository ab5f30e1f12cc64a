#include "facet/support/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <system_error>

namespace facet::support {
namespace fs = std::filesystem;

namespace {

std::string error_text(int error) { return std::error_code(error, std::generic_category()).message(); }

// A new empty file "<target>.tmp.<pid>.<8 random letters><extension>", or
// an error. Like mkstemps, but with mode 0666 less the umask (mkstemps makes
// 0600, and the temporary becomes the output); the process id tells whose
// temporary a killed build left.
Result<std::string, std::string> create_temporary(const fs::path& target) {
  const std::string prefix = target.string() + ".tmp." + std::to_string(::getpid()) + ".";
  constexpr std::string_view kLetters = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device entropy;
  int error = EEXIST;
  for (int attempt = 0; attempt < 100 && error == EEXIST; ++attempt) {
    std::string name = prefix;
    for (int i = 0; i < 8; ++i) name += kLetters[entropy() % kLetters.size()];
    name += target.extension().string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return name;
    }
    error = errno;
  }
  return unexpected(error_text(error));
}

using Writer = std::function<Result<void, std::string>(const std::string&)>;

// An existing target that is no regular file: renaming over it would put a
// file in the place of a device node (as root, `-o /dev/null` would replace
// the system's /dev/null) or of a FIFO. A character device and a FIFO that
// a process reads are written in place; anything else is refused. nullopt:
// the target is a regular file or does not exist.
std::optional<Result<void, std::string>> write_special_target(const std::string& target, const Writer& write) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return std::nullopt;
  if (S_ISDIR(st.st_mode)) return unexpected(std::string("it is a folder"));
  if (S_ISCHR(st.st_mode)) return write(target);
  if (!S_ISFIFO(st.st_mode)) return unexpected(std::string("it is not a regular file"));
  // Opening a FIFO for writing waits for a reader: without one, an error
  // instead of a hang. The probe stays open while the writer writes, so that
  // the reader does not see the end of the stream between the two.
  const int probe = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (probe < 0) {
    return unexpected(errno == ENXIO ? std::string("it is a FIFO that no process is reading") : error_text(errno));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{probe};
  return write(target);
}

}  // namespace

Result<void, std::string> replace_file_atomically(
    const std::string& target,
    const std::function<Result<void, std::string>(const std::string& temporary)>& write_temporary,
    SpecialTarget special) {
  if (special == SpecialTarget::write_in_place) {
    if (auto written = write_special_target(target, write_temporary)) return std::move(*written);
  }
  Result<std::string, std::string> temporary = create_temporary(fs::path(target));
  if (!temporary) return unexpected(temporary.error());
  std::error_code ignored;
  if (Result<void, std::string> written = write_temporary(*temporary); !written) {
    fs::remove(*temporary, ignored);
    return written;
  }
  // Atomic: readers see the old file or the new one. A folder (or anything
  // else that cannot be replaced) in the target's place makes it fail.
  std::error_code ec;
  fs::rename(*temporary, target, ec);
  if (ec) {
    fs::remove(*temporary, ignored);
    return unexpected(ec.message());
  }
  return {};
}

Result<void, std::string> write_file_atomically(const std::string& target, std::string_view bytes,
                                                SpecialTarget special) {
  return replace_file_atomically(
      target,
      [&](const std::string& temporary) -> Result<void, std::string> {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) return unexpected(error_text(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out) return unexpected(std::string("the write failed"));
        return {};
      },
      special);
}

}  // namespace facet::support
