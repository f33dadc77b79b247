#include "common/io/output_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "common/error.h"

namespace voxgi {
namespace {

namespace fs = std::filesystem;

std::string reason(int error) {
  return std::strerror(error);
}

// SIGINT and SIGTERM that arrive while a temporary exists are held (any thread may receive them)
// and raised again with their default action once it is renamed or removed.
std::atomic<int> writesInProgress{0};
std::atomic<int> heldSignal{0};
std::once_flag handlersInstalled;
struct sigaction previous[2];

void hold(int signal) {
  if (writesInProgress.load() > 0) {
    heldSignal.store(signal);
    return;
  }
  sigaction(signal, &previous[signal == SIGINT ? 0 : 1], nullptr);
  raise(signal);
}

void installHandlers() {
  std::call_once(handlersInstalled, [] {
    struct sigaction action {};
    action.sa_handler = hold;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 2; ++i) {
      const int signal = i == 0 ? SIGINT : SIGTERM;
      sigaction(signal, nullptr, &previous[i]);
      // A command that handles the signal itself (the path tracer's cancel) keeps its handler.
      if (previous[i].sa_handler == SIG_DFL) sigaction(signal, &action, nullptr);
    }
  });
}

// Counts one write in progress; at the end, raises a signal that arrived meanwhile.
struct WriteWindow {
  WriteWindow() {
    installHandlers();
    ++writesInProgress;
  }
  ~WriteWindow() {
    if (--writesInProgress == 0) {
      const int signal = heldSignal.exchange(0);
      if (signal != 0) hold(signal);
    }
  }
};

// A temporary file next to `path`, removed unless released.
struct Temporary {
  std::string name;
  int fd = -1;
  explicit Temporary(const std::string& path) {
    // A hidden name no user picks, unique by mkstemp; appended piecewise (GCC 12 warns falsely,
    // -Wrestrict, on a chained string operator+).
    const fs::path target(path);
    std::string hidden(".");
    hidden.append(target.filename().string()).append(".voxgi-XXXXXX");
    std::string pattern = (target.parent_path() / hidden).string();
    fd = mkstemp(pattern.data());
    if (fd < 0) throw InputError(path, "", "cannot write: " + reason(errno));
    name = pattern;
  }
  ~Temporary() {
    if (fd >= 0) close(fd);
    if (!name.empty()) unlink(name.c_str());
  }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
};

}  // namespace

void checkOutputPath(const std::string& path) {
  if (path.empty()) throw InputError("(empty path)", "", "cannot write: no file name");
  const fs::path target(path);
  struct stat st {};
  if (lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode))
      throw InputError(path, "",
                       "is a symbolic link; voxgi replaces regular files only (write to where it "
                       "points instead)");
    if (!S_ISREG(st.st_mode)) throw InputError(path, "", "exists and is not a regular file");
  } else if (errno != ENOENT) {
    throw InputError(path, "", "cannot write: " + reason(errno));
  }
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  struct stat ds {};
  if (stat(dir.c_str(), &ds) != 0)
    throw InputError(path, "", "cannot write: folder " + dir.string() + ": " + reason(errno));
  if (!S_ISDIR(ds.st_mode))
    throw InputError(path, "", "cannot write: " + dir.string() + " is not a folder");
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(path, "", "cannot write: folder " + dir.string() + ": " + reason(errno));
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  checkOutputPath(path);
  const WriteWindow window;
  Temporary tmp(path);
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(tmp.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(path, "", "cannot write: " + reason(n < 0 ? errno : EIO));
    done += size_t(n);
  }
  // Ordinary files get the permissions a plain open would give them (mkstemp uses 0600).
  const mode_t mask = umask(0);
  umask(mask);
  if (fchmod(tmp.fd, 0666 & ~mask) != 0 || fsync(tmp.fd) != 0)
    throw InputError(path, "", "cannot write: " + reason(errno));
  const int fd = tmp.fd;
  tmp.fd = -1;
  if (close(fd) != 0) throw InputError(path, "", "cannot write: " + reason(errno));
  if (rename(tmp.name.c_str(), path.c_str()) != 0)
    throw InputError(path, "", "cannot write: " + reason(errno));
  tmp.name.clear();  // renamed: nothing to remove
}

void prepareOutputFolder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(
        dir, "",
        "cannot create the output folder: " + (ec ? ec.message() : std::string("not a folder")));
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(dir, "", "cannot write into the output folder: " + reason(errno));
}

}  // namespace voxgi
