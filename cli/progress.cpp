#include "cli/progress.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace coatfft::cli {

bool progress_wanted(bool quiet, bool stderr_is_terminal) {
  return stderr_is_terminal && !quiet;
}

Progress::Progress(bool enabled, std::ostream& out, Clock::time_point start)
    : enabled_(enabled), out_(out), start_(start), last_print_(start - interval) {}

Progress::~Progress() {
  end_line();
}

bool Progress::due(Clock::time_point now) const {
  return enabled_ && now - start_ >= delay;
}

// "coatfft [12.3 s] ": the time since the start leads every line, so that a stage's line also
// tells how long the stages before it took.
std::string Progress::prefix(Clock::time_point now) const {
  const std::chrono::duration<double> elapsed = now - start_;
  std::ostringstream text;
  text << "coatfft [" << std::fixed << std::setprecision(1) << elapsed.count() << " s] ";
  return text.str();
}

void Progress::end_line() {
  if (open_line_ == 0) return;
  out_ << '\n' << std::flush;
  open_line_ = 0;
}

void Progress::stage(std::string_view what, Clock::time_point now) {
  // Not throttled: a run has a handful of stages, and a stage left on the screen after it has
  // ended would be wrong for as long as the next one takes.
  stage_ = what;
  step_.clear();
  if (!due(now)) return;
  write_line(prefix(now) + stage_, now);
}

// A line of its own, after the open line if there is one.
void Progress::write_line(const std::string& line, Clock::time_point now) {
  end_line();
  out_ << line << '\n' << std::flush;
  last_print_ = now;
  printed_ = true;
}

// One line, rewritten in place ('\r') by the next.
void Progress::write_open_line(std::string line, Clock::time_point now) {
  // Blanks cover what is left of a longer line before ("iteration 100" then "iteration 99").
  if (line.size() < open_line_) line.append(open_line_ - line.size(), ' ');
  out_ << '\r' << line << std::flush;
  open_line_ = line.size();
  last_print_ = now;
  printed_ = true;
}

// "<stage>: <step>", or the stage alone.
std::string Progress::activity() const {
  return step_.empty() ? stage_ : stage_ + ": " + step_;
}

void Progress::step(std::string_view what, Clock::time_point now) {
  step_ = what;
  if (!due(now) || now - last_print_ < interval) return;
  write_line(prefix(now) + activity(), now);
}

// A line of its own, not an update in place: a long stage leaves a line per second, which a
// terminal scrolls and a reader of lines (a log of the terminal, `script`) sees too.
void Progress::tick(Clock::time_point now) {
  if (stage_.empty() || !due(now) || now - last_print_ < tick_interval) return;
  write_line(prefix(now) + activity() + " ...", now);
}

void Progress::iteration(int k, double residual, Clock::time_point now) {
  if (!due(now) || now - last_print_ < interval) return;
  std::ostringstream text;
  text << prefix(now) << (step_.empty() ? "" : step_ + ", ") << "contact solve: iteration " << k
       << ", residual " << std::setprecision(2) << residual;
  write_open_line(text.str(), now);
}

void Progress::finish(Clock::time_point now) {
  if (printed_) stage("done", now);
}

}  // namespace coatfft::cli
