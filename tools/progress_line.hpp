// A progress line on a terminal: one line on stderr, redrawn in place with '\r', with the work
// done, the rate and the time left, at most a few times a second, and erased at the end. Drawn
// only when the stream is a terminal (isatty): never into a file or a pipe, so that scripts,
// tests and results see nothing of it. Any command that runs long hooks it into the library's
// progress callbacks (stickslip/progress.hpp):
//
//   ProgressLine line("sweep");
//   options.progress = line.Callback();
//   ... the work ...
//   line.Clear();  // also on destruction
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>

#include "stickslip/progress.hpp"

namespace stickslip::cli {

struct ProgressLineOptions {
  // Nothing is drawn before the work has run this long (a quick command shows no line) ...
  std::chrono::duration<double> first_after{0.5};
  // ... nor more often than this.
  std::chrono::duration<double> interval{0.2};
  // How the value of a Progress is named on the line ("omega" for a continuation in omega), or
  // empty to leave it out.
  std::string value_name;
};

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  // Draws on stderr if stderr is a terminal.
  explicit ProgressLine(std::string label, ProgressLineOptions options = {});
  // Draws on `stream` if `enabled` (tests draw into a file, with a clock of their own).
  ProgressLine(std::string label, ProgressLineOptions options, std::FILE* stream, bool enabled,
               std::function<Clock::time_point()> now = Clock::now);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Redraws the line if it is due. Thread-safe.
  void Update(const Progress& progress);
  // A callback for the library's options that calls Update, valid while this line lives; empty
  // when no line is drawn, so that the library does not report for nothing.
  ProgressCallback Callback();
  // Erases the line, if one was drawn. Thread-safe; Update after it draws again.
  void Clear();

  bool enabled() const { return enabled_; }

  // The text of the line: "<label>: 120/400 points (30%), 25.1 points/s, 11 s left, omega = 0.61".
  // Public for tests.
  static std::string Text(const std::string& label, const Progress& progress, double seconds,
                          const std::string& value_name);

 private:
  std::string label_;
  ProgressLineOptions options_;
  std::FILE* stream_;
  bool enabled_;
  std::function<Clock::time_point()> now_;
  Clock::time_point started_;
  Clock::time_point last_drawn_;
  bool drawn_ = false;
  std::size_t width_ = 0;  // of the text last drawn, to erase it
  std::size_t columns_ = 80;  // the terminal's width (80 if unknown): longer texts are cut
  std::mutex mutex_;
};

}  // namespace stickslip::cli
