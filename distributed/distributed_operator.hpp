#pragma once
// A surface operator on fields held in row slabs (distributed/slab.hpp) by the ranks of a
// communicator: apply() takes this rank's rows (nx, rows) of the pressure [Pa] and resizes the
// displacement [m] to them; it is collective, and refuses a pressure of another shape, or one with
// a value that is not finite on any rank, with InvalidArgument on every rank (check_pressure, or
// check_shape and check_displacement). What
// the distributed contact solver (distributed_contact.hpp) needs of an operator: its slab, its
// communicator, and the time its transposes took.
#include <string_view>

#include "../convolution/operators/surface_operator.hpp"
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "communicator.hpp"
#include "slab.hpp"

namespace coatfft {

class DistributedOperator : public SurfaceOperator {
 public:
  const Grid& grid() const final { return grid_; }
  /// This rank's rows and half-spectrum columns.
  virtual const Slab& slab() const = 0;
  const Communicator& communicator() const { return comm_; }
  /// The wall time apply() and the construction spent in the transforms' transposes so far [s]:
  /// the communication between the ranks, and the wait for the slowest.
  virtual double communication_seconds() const = 0;
  /// This rank's rows of the displacement under 1 Pa on cell (0, 0). Collective.
  Field unit_response() override;

 protected:
  DistributedOperator(const Communicator& comm, const Grid& grid) : comm_(comm), grid_(grid) {}
  /// Refuses, on every rank together (a rank that threw alone would leave the others waiting), a
  /// rank's pressure that is not of its slab's shape or is its displacement, and a value that is
  /// not finite on any rank, in one reduction; `who` names the operator in the message.
  void check_pressure(const Field& pressure, const Field& displacement, std::string_view who) const;
  /// The same refusals for an operator whose every displacement sums every pressure (a periodic
  /// one): the shape before the transforms (check_shape), and a value that is not finite after
  /// them from one displacement of each rank (check_displacement), instead of a pass over the
  /// pressure. Each agrees over the ranks in one reduction.
  void check_shape(const Field& pressure, const Field& displacement, std::string_view who) const;
  void check_displacement(const Field& displacement, std::string_view who) const;

 private:
  Communicator comm_;
  Grid grid_;
};

}  // namespace coatfft
