// An X server of a test program's own, for the tests of windows (serve's windows, the GLFW
// context, swap groups). Xvfb started with -displayfd picks a display number nobody uses and
// writes it to our pipe once it accepts connections (Xserver(1)), so programs running side by
// side never race for one number the way `xvfb-run -a` does (it looks for a free lock file,
// then starts the server: two at once can pick the same number).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace skyig::testing {

class VirtualX {
 public:
  // `screen` is Xvfb's -screen argument (WIDTHxHEIGHTxDEPTH); the server's own messages go to
  // `log` so that a test can show them when the server did not start.
  explicit VirtualX(const std::string& screen = "1024x256x24", const std::string& log = "/dev/null") {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(fds[0]);
      if (const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644); out >= 0) ::dup2(out, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp",
               "-noreset", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    std::string number;
    char c;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~VirtualX() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  VirtualX(const VirtualX&) = delete;
  VirtualX& operator=(const VirtualX&) = delete;

  // ":N", or empty where Xvfb is missing or did not start.
  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace skyig::testing
