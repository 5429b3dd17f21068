#include "x_display.h"

#include <X11/Xlib.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <utility>

extern char** environ;

namespace tissue::inspect {
namespace {

/// Reads the display number Xvfb writes to -displayfd ("N\n"); empty when it died first.
std::string readDisplayNumber(int fd) {
  std::string number;
  char c = 0;
  while (read(fd, &c, 1) == 1 && c != '\n')
    number.push_back(c);
  return number;
}

void stopServer(pid_t server) {
  if (server <= 0) return;
  kill(server, SIGTERM);
  int status = 0;
  waitpid(server, &status, 0);
}

}  // namespace

Result<XDisplay> XDisplay::open() {
  // An existing display (a desktop, or xvfb-run) is used as it is.
  if (const char* name = std::getenv("DISPLAY"); name && *name) {
    if (Display* display = XOpenDisplay(name)) return XDisplay(display, -1);
  }
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return Error{"chart: cannot create a pipe to start Xvfb"};
  // The write end must survive exec in the child only: dup it to a known descriptor.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::string arg0 = "Xvfb", fdFlag = "-displayfd", fdValue = "3", screenFlag = "-screen", screen = "0",
              size = "1920x1200x24", tcp = "-nolisten", tcpValue = "tcp";
  char* argv[] = {arg0.data(), fdFlag.data(),   fdValue.data(), screenFlag.data(), screen.data(), size.data(),
                  tcp.data(),  tcpValue.data(), nullptr};
  pid_t server = -1;
  const int spawned = posix_spawnp(&server, "Xvfb", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    return Error{
        "chart: no X display and Xvfb could not be started; install the 'xvfb' package "
        "(scripts/install-deps.sh) or set DISPLAY"};
  }
  const std::string number = readDisplayNumber(fds[0]);
  ::close(fds[0]);
  Display* display = number.empty() ? nullptr : XOpenDisplay((":" + number).c_str());
  if (!display) {
    stopServer(server);
    return Error{
        "chart: Xvfb started but its display could not be opened; check that Xvfb runs "
        "(try 'xvfb-run -a true')"};
  }
  return XDisplay(display, server);
}

XDisplay::XDisplay(XDisplay&& other) noexcept
    : m_display(std::exchange(other.m_display, nullptr)), m_server(std::exchange(other.m_server, -1)) {}

XDisplay& XDisplay::operator=(XDisplay&& other) noexcept {
  if (this != &other) {
    close();
    m_display = std::exchange(other.m_display, nullptr);
    m_server = std::exchange(other.m_server, -1);
  }
  return *this;
}

XDisplay::~XDisplay() {
  close();
}

void XDisplay::close() {
  if (m_display) XCloseDisplay(m_display);
  m_display = nullptr;
  stopServer(m_server);
  m_server = -1;
}

}  // namespace tissue::inspect
