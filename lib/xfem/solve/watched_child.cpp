// SPDX-License-Identifier: MIT
#include "xfem/solve/watched_child.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "xfem/core/error.h"

namespace xfem {
namespace {

// Lines of Open MPI's help texts that carry no words: rules and blank lines.
bool is_rule(const std::string& line) {
  return line.find_first_not_of("-*= \t\r") == std::string::npos;
}

// "[vm:04718] *** An error ..." -> "An error ...".
std::string without_prefixes(std::string line) {
  if (!line.empty() && line[0] == '[') {
    const auto close = line.find("] ");
    if (close != std::string::npos) line = line.substr(close + 2);
  }
  const auto start = line.find_first_not_of("* \t");
  return start == std::string::npos ? std::string() : line.substr(start);
}

// Where the first sentence of `text` ends (after its '.', ':', '!' or '?' followed by a space or
// the end), or npos.
std::size_t sentence_end(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i)
    if (std::strchr(".:!?", text[i]) && (i + 1 == text.size() || text[i + 1] == ' ')) return i + 1;
  return std::string::npos;
}

}  // namespace

std::string first_meaningful_line(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& raw : lines) {
    if (is_rule(raw)) {
      if (text.empty()) continue;
      break;  // the end of the first paragraph
    }
    const std::string line = without_prefixes(raw);
    if (line.empty()) continue;
    text += (text.empty() ? "" : " ") + line;
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
    const std::size_t end = sentence_end(text);
    if (end != std::string::npos) {
      text.resize(end);
      break;
    }
    if (text.size() >= 200) break;
  }
  if (text.size() > 200) text = text.substr(0, 200) + "...";
  return text;
}

std::string describe_status(const WatchedRun& run) {
  if (!run.signaled) return "exit status " + std::to_string(run.status);
  const char* name = ::strsignal(run.status);
  return "killed by signal " + std::to_string(run.status) + (name ? std::string(" (") + name + ")" : "");
}

WatchedRun run_watched(const std::vector<std::string>& args, bool search_path, const std::string& own_prefix) {
  WatchedRun run;
  int err[2], exec_report[2];
  if (::pipe(err) != 0) throw Error(std::string("cannot make a pipe: ") + std::strerror(errno));
  if (::pipe2(exec_report, O_CLOEXEC) != 0) {
    ::close(err[0]), ::close(err[1]);
    throw Error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  std::vector<char*> cargs;
  for (const auto& a : args) cargs.push_back(const_cast<char*>(a.c_str()));
  cargs.push_back(nullptr);
  std::fflush(stdout);
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(std::string("cannot start ") + args[0] + ": " + std::strerror(errno));
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // killed with xfem-solve (timeout, ^C), not left running
    ::dup2(err[1], 2);
    ::close(err[0]), ::close(err[1]), ::close(exec_report[0]);
    if (search_path)
      ::execvp(cargs[0], cargs.data());
    else
      ::execv(cargs[0], cargs.data());
    const int e = errno;  // the exec failed: say why through the close-on-exec pipe
    (void)!::write(exec_report[1], &e, sizeof e);
    ::_exit(127);
  }
  ::close(err[1]), ::close(exec_report[1]);
  int exec_errno = 0;
  run.started = ::read(exec_report[0], &exec_errno, sizeof exec_errno) != static_cast<ssize_t>(sizeof exec_errno);
  ::close(exec_report[0]);
  if (!run.started) run.exec_error = std::strerror(exec_errno);

  // Read stderr until every writer closed it, or for at most 1 s after the child exited (a
  // daemon it left behind may hold the pipe).
  std::string pending;
  const auto take_lines = [&](bool flush_rest) {
    std::size_t nl;
    while ((nl = pending.find('\n')) != std::string::npos || (flush_rest && !pending.empty())) {
      const std::string line = nl == std::string::npos ? pending : pending.substr(0, nl);
      pending.erase(0, nl == std::string::npos ? pending.size() : nl + 1);
      if (line.rfind(own_prefix, 0) == 0) {
        std::cerr << line << "\n" << std::flush;
        if (line.compare(own_prefix.size(), 6, "error:") == 0) run.printed_error = true;
      } else {
        run.other_lines.push_back(line);
      }
    }
  };
  int wait_status = 0;
  bool reaped = false;
  auto deadline = std::chrono::steady_clock::time_point::max();
  for (;;) {
    pollfd p{err[0], POLLIN, 0};
    if (::poll(&p, 1, 100) > 0) {
      char buf[4096];
      const ssize_t n = ::read(err[0], buf, sizeof buf);
      if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) break;
      if (n > 0) pending.append(buf, static_cast<std::size_t>(n));
      take_lines(false);
    }
    if (!reaped && ::waitpid(pid, &wait_status, WNOHANG) == pid) {
      reaped = true;
      deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    }
    if (reaped && std::chrono::steady_clock::now() > deadline) break;
  }
  ::close(err[0]);
  take_lines(true);
  while (!reaped && ::waitpid(pid, &wait_status, 0) < 0 && errno == EINTR) {
  }
  run.signaled = WIFSIGNALED(wait_status);
  run.status = run.signaled ? WTERMSIG(wait_status) : WEXITSTATUS(wait_status);
  return run;
}

}  // namespace xfem
