#include "fieldviz/core/ChildProcess.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace fluidviz {

namespace {

std::runtime_error failure(const std::string& what, int error) {
  return std::runtime_error(what + ": " + std::strerror(error));
}

// stderr goes to an unlinked temporary file rather than a second pipe: a child that fills one
// pipe while the parent waits on the other would stall both.
int temporaryFile() {
  char name[] = "/tmp/fluidviz_child_XXXXXX";
  const int fd = ::mkostemp(name, O_CLOEXEC);
  if (fd < 0) throw failure("cannot create a temporary file", errno);
  ::unlink(name);
  return fd;
}

std::string readWholeFile(int fd) {
  std::string text;
  ::lseek(fd, 0, SEEK_SET);
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(fd, buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  return text;
}

void forwardUntilEnd(int fd, const std::function<void(std::string_view)>& onOutput) {
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0)
      onOutput(std::string_view(buffer, static_cast<std::size_t>(n)));
    else if (n == 0 || errno != EINTR)
      return;
  }
}

int waitFor(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

ChildProcessResult runChildProcess(const std::vector<std::string>& argv,
                                   const std::function<void(std::string_view)>& onOutput) {
  if (argv.empty()) throw std::invalid_argument("runChildProcess: no program given");
  const int errFd = temporaryFile();
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) {
    const int error = errno;
    ::close(errFd);
    throw failure("cannot create a pipe for " + argv[0], error);
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, errFd, STDERR_FILENO);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawnError = ::posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (spawnError != 0) {
    ::close(out[0]);
    ::close(errFd);
    throw failure("cannot start " + argv[0], spawnError);
  }
  forwardUntilEnd(out[0], onOutput);
  ::close(out[0]);
  ChildProcessResult result;
  result.status = waitFor(pid);
  result.errors = readWholeFile(errFd);
  ::close(errFd);
  return result;
}

bool exitedWithZero(int status) { return WIFEXITED(status) && WEXITSTATUS(status) == 0; }

std::string exitDescription(int status) {
  if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

}  // namespace fluidviz
