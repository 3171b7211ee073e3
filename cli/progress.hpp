#pragma once
// Progress of `coatfft run` on a terminal (docs/scene_format.md, "Progress on the terminal"): the
// stage a long run is in, the step of a stage made of many (a sweep's value, a plane of the
// stresses) and the iterations of a contact solve. A run that ends within a second
// prints nothing, and nothing is printed under --quiet or when stderr is not a terminal, so that
// scripts and tests see only warnings and errors there.
//
// Progress is reported from the computing thread, between the steps it already takes: a stage is
// announced when it starts, and while it runs the library's interrupt checks (core/interrupt.hpp,
// every 50 ms or so) call tick(), which prints a line with the elapsed time once a second, so a
// long stage (the operator's or the stresses' set-up) is never silent for a second. No thread or
// timer is needed, and nothing else writing to stderr (warnings) can be interleaved with a progress
// line.
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>

#include "scene/progress_observer.hpp"

namespace coatfft::cli {

/// Whether `coatfft run` reports progress: only on a terminal, and not under --quiet.
bool progress_wanted(bool quiet, bool stderr_is_terminal);

/// Progress lines on one stream: the scene layer's observer (scene/progress_observer.hpp) for a
/// terminal. Nothing is printed before `delay` has passed since the start; after it every stage
/// is one line, a step one line at most once per `interval`, a stage still running one line once
/// per `tick_interval`, and iterations update one line in place ('\r') at most once per
/// `interval`, so that a terminal gets a few lines per second at most.
class Progress : public scene::ProgressObserver {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds delay{1000};
  static constexpr std::chrono::milliseconds interval{250};
  /// How often tick() shows that a stage is still running: below a second, since the interrupt
  /// checks that call it come every 50 ms or so, and a stage is never silent for a second.
  static constexpr std::chrono::milliseconds tick_interval{900};

  /// Prints on `out` when `enabled`; the run's time counts from `start`.
  Progress(bool enabled, std::ostream& out, Clock::time_point start = Clock::now());
  /// Ends a line that iteration() left open, so that what follows on the stream (an error
  /// message) starts a line of its own.
  ~Progress() override;
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// A stage begins, e.g. "setting up the operator (dcfft)", at `now`.
  void stage(std::string_view what, Clock::time_point now);
  void stage(std::string_view what) override { stage(what, Clock::now()); }
  /// A step of the current stage begins, e.g. "load 3 of 8: 120 N", at `now`: a line of the
  /// stage and step; the following iterations' lines name the step.
  void step(std::string_view what, Clock::time_point now);
  void step(std::string_view what) override { step(what, Clock::now()); }
  /// The current stage is still running: once `tick_interval` has passed since the last line, a
  /// line "coatfft [12.3 s] <stage>: <step> ...".
  void tick(Clock::time_point now = Clock::now());
  /// Iteration `k` of a contact solve left `residual`, at `now`.
  void iteration(int k, double residual, Clock::time_point now);
  void iteration(int k, double residual) override { iteration(k, residual, Clock::now()); }
  /// The run is done: a last line with its total time, if anything was printed before.
  void finish(Clock::time_point now = Clock::now());

 private:
  bool due(Clock::time_point now) const;
  std::string prefix(Clock::time_point now) const;
  std::string activity() const;
  void write_line(const std::string& line, Clock::time_point now);
  void end_line();
  void write_open_line(std::string line, Clock::time_point now);

  bool enabled_;
  std::ostream& out_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  bool printed_ = false;
  std::string stage_;          ///< the current stage, for tick()
  std::string step_;           ///< the current step of the stage; empty when none
  std::size_t open_line_ = 0;  ///< length of the line left open (iteration); 0 when none is
};

}  // namespace coatfft::cli
