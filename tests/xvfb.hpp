#pragma once
// An X server of the test's own (Xvfb), for the viewer's window. Xvfb picks
// a free display number itself (-displayfd), so tests running side by side
// never share one. A missing Xvfb is an error the test reports, never a skip.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "process.hpp"

namespace tp::test {

class XvfbServer {
 public:
  // Xvfb's own messages go to `logPath`.
  explicit XvfbServer(const std::string& logPath) {
    int fds[2];
    if (pipe(fds) != 0) {
      error_ = "pipe() failed";
      return;
    }
    const std::string fd = std::to_string(fds[1]);  // made before fork: the child only opens, dups and execs
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      const int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null = open("/dev/null", O_RDONLY);
      dup2(null, 0);
      dup2(log, 1);
      dup2(log, 2);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      static const char message[] = "cannot run Xvfb: it is not on the PATH\n";
      (void)!write(2, message, sizeof message - 1);
      _exit(127);
    }
    close(fds[1]);
    if (pid_ < 0) {
      close(fds[0]);
      error_ = "fork() failed";
      return;
    }
    // Xvfb writes the display number when it accepts connections.
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    char c;
    while (poll(&p, 1, 20000) == 1 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (number.empty()) {
      error_ = "Xvfb did not start (tools/setup.sh installs the xvfb package); its log: " + readText(logPath);
      return;
    }
    display_ = ":" + number;
  }
  ~XvfbServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;

  // ":N", or empty when the server did not start (then error() says why).
  const std::string& display() const { return display_; }
  const std::string& error() const { return error_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
  std::string error_;
};

}  // namespace tp::test
