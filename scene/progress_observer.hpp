#pragma once
// What a scene's computation reports while it runs: the stage it enters ("setting up the
// operator (dcfft)"), the step of a stage made of many (the value of a sweep, the normal solve of
// a friction coupling, the planes of the stresses) and the iterations of a contact solve. A front
// end that shows progress implements it (the program's terminal lines, cli/progress.hpp); the scene
// layer never writes to a stream itself, and the default observer reports nothing.
#include <string_view>

namespace coatfft::scene {

class ProgressObserver {
 public:
  virtual ~ProgressObserver() = default;
  /// A stage begins; it lasts until the next one.
  virtual void stage(std::string_view /*what*/) {}
  /// A step of the current stage begins ("load 3 of 8: 120 N"); it lasts until the next step or
  /// stage, and the iterations of a contact solve are the step's.
  virtual void step(std::string_view /*what*/) {}
  /// Iteration `k` of a contact solve left `residual` (ContactOptions::on_iteration).
  virtual void iteration(int /*k*/, double /*residual*/) {}
};

}  // namespace coatfft::scene
