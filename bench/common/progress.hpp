// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace projtrack::bench {

class Progress {
 public:
  explicit Progress(long total) : total_(total), tty_(isatty(fileno(stderr))) {}
  ~Progress() {
    if (tty_) std::fputc('\n', stderr);
  }
  void advance(const std::string& what, long steps = 1) {
    done_ += steps;
    if (!tty_) return;
    const double f = total_ ? static_cast<double>(done_) / total_ : 1.0;
    const int filled = static_cast<int>(f * 30);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = f > 0.01 ? elapsed * (1 - f) / f : 0;
    std::fprintf(stderr, "\r[%-30s] %3.0f%%  %4.0fs left  %-40.40s",
                 std::string(filled, '#').c_str(), 100 * f, left, what.c_str());
    std::fflush(stderr);
  }

 private:
  long total_, done_ = 0;
  bool tty_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace projtrack::bench
