/// @file process.cpp
/// posix_spawnp with two pipes drained by poll(), so neither stream can block the child.

#include "attiguard/cli/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <system_error>

namespace attiguard::cli {
namespace {

/// A file descriptor closed on destruction.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  [[nodiscard]] int get() const { return fd_; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_{-1};
};

/// A pipe whose ends are closed on exec (dup2 onto 1 and 2 in the child clears that flag).
struct Pipe {
  Fd read_end;
  Fd write_end;
};

void make_pipe(Pipe& p) {
  std::array<int, 2> fds{};
  if (::pipe(fds.data()) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  p.read_end.reset(fds[0]);
  p.write_end.reset(fds[1]);
  ::fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);
}

/// posix_spawn_file_actions_t with RAII.
class FileActions {
 public:
  FileActions() { ::posix_spawn_file_actions_init(&actions_); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  ~FileActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_{};
};

/// Null-terminated array of pointers into `strings` (which must outlive it).
std::vector<char*> c_strings(const std::vector<std::string>& strings) {
  std::vector<char*> out;
  out.reserve(strings.size() + 1);
  for (const auto& s : strings) out.push_back(const_cast<char*>(s.c_str()));
  out.push_back(nullptr);
  return out;
}

/// Reads both pipes until each reaches its end (or a read error), appending to `out` and `err`.
void drain_pipes(const Pipe& out_pipe, const Pipe& err_pipe, std::string& out, std::string& err) {
  std::array<pollfd, 2> fds{pollfd{out_pipe.read_end.get(), POLLIN, 0},
                            pollfd{err_pipe.read_end.get(), POLLIN, 0}};
  std::array<std::string*, 2> sinks{&out, &err};
  std::array<char, 4096> buffer{};
  int open_streams = 2;
  while (open_streams > 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
      if (n > 0) {
        sinks[i]->append(buffer.data(), static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        fds[i].fd = -1;  // end of stream (or a read error): stop polling it
        --open_streams;
      }
    }
  }
}

/// Waits for the child `pid` and records how it ended (nothing when waitpid fails).
void wait_child(pid_t pid, ProcessResult& result) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return;
  }
  if (WIFEXITED(status)) {
    result.exited = true;
    result.exit_status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::vector<std::string>& env) {
  ProcessResult result;
  if (argv.empty()) {
    result.spawn_error = EINVAL;
    return result;
  }
  Pipe out_pipe;
  Pipe err_pipe;
  make_pipe(out_pipe);
  make_pipe(err_pipe);

  FileActions actions;
  ::posix_spawn_file_actions_addopen(actions.get(), STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_adddup2(actions.get(), out_pipe.write_end.get(), STDOUT_FILENO);
  ::posix_spawn_file_actions_adddup2(actions.get(), err_pipe.write_end.get(), STDERR_FILENO);

  auto argv_c = c_strings(argv);
  auto env_c = c_strings(env);
  pid_t pid = -1;
  const int rc =
      ::posix_spawnp(&pid, argv_c[0], actions.get(), nullptr, argv_c.data(), env_c.data());
  out_pipe.write_end.reset();
  err_pipe.write_end.reset();
  if (rc != 0) {
    result.spawn_error = rc;
    return result;
  }
  drain_pipes(out_pipe, err_pipe, result.out, result.err);
  wait_child(pid, result);
  return result;
}

}  // namespace attiguard::cli
