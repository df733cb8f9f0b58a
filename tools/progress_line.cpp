#include "progress_line.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace stickslip::cli {

namespace {

// "7 s", "3 min 5 s", "2 h 4 min".
std::string Duration(double seconds) {
  const long s = std::lround(std::min(seconds, 1e8));
  if (s < 60) return fmt::format("{} s", s);
  if (s < 3600) return fmt::format("{} min {} s", s / 60, s % 60);
  return fmt::format("{} h {} min", s / 3600, s % 3600 / 60);
}

}  // namespace

ProgressLine::ProgressLine(std::string label, ProgressLineOptions options)
    : ProgressLine(std::move(label), std::move(options), stderr, ::isatty(STDERR_FILENO) == 1) {}

ProgressLine::ProgressLine(std::string label, ProgressLineOptions options, std::FILE* stream, bool enabled,
                           std::function<Clock::time_point()> now)
    : label_(std::move(label)), options_(std::move(options)), stream_(stream), enabled_(enabled),
      now_(std::move(now)), started_(now_()), last_drawn_(started_) {
  // A line longer than the terminal would wrap, and '\r' return to the wrong line.
  winsize size{};
  if (enabled_ && ::ioctl(::fileno(stream_), TIOCGWINSZ, &size) == 0 && size.ws_col > 1) columns_ = size.ws_col;
}

ProgressLine::~ProgressLine() { Clear(); }

std::string ProgressLine::Text(const std::string& label, const Progress& p, double seconds,
                               const std::string& value_name) {
  std::string text = fmt::format("{}: {:.6g}/{:.6g} {}", label, p.done, p.total, p.unit);
  if (p.total > 0.0) text += fmt::format(" ({:.0f}%)", 100.0 * std::clamp(p.done / p.total, 0.0, 1.0));
  const double rate = seconds > 0.0 ? p.done / seconds : 0.0;
  if (rate > 0.0) {
    text += fmt::format(", {:.3g} {}/s, {} left", rate, p.unit, Duration(std::max(0.0, p.total - p.done) / rate));
  }
  if (!value_name.empty() && std::isfinite(p.value)) text += fmt::format(", {} = {:.8g}", value_name, p.value);
  return text;
}

void ProgressLine::Update(const Progress& progress) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const Clock::time_point now = now_();
  if (now - started_ < options_.first_after || (drawn_ && now - last_drawn_ < options_.interval)) return;
  std::string text =
      Text(label_, progress, std::chrono::duration<double>(now - started_).count(), options_.value_name);
  if (text.size() >= columns_) text.resize(columns_ - 1);
  // Padded over the last text, so that a shorter line leaves nothing of the longer one.
  fmt::print(stream_, "\r{:<{}}", text, width_);
  std::fflush(stream_);
  width_ = std::max(width_, text.size());
  drawn_ = true;
  last_drawn_ = now;
}

ProgressCallback ProgressLine::Callback() {
  if (!enabled_) return {};  // no line: the library need not report at all
  return [this](const Progress& progress) { Update(progress); };
}

void ProgressLine::Clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!drawn_) return;
  fmt::print(stream_, "\r{:<{}}\r", "", width_);
  std::fflush(stream_);
  drawn_ = false;
  width_ = 0;
  started_ = now_();  // a later Update starts a new line, after the same delay
}

}  // namespace stickslip::cli
