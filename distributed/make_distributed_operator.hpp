#pragma once
// The distributed operators' factory, beside make_operator
// (convolution/operators/make_operator.hpp): the same grid, body (a LayerStack, or any Frf) and
// OperatorOptions in; the DistributedOperator on the ranks of a communicator and the same
// OperatorReport out. Nothing else maps a Method to a distributed class. Which methods run
// distributed, on which boundary, is runs_distributed(); the others are refused by name.
// Collective.
#include <memory>

#include "../convolution/operators/make_operator.hpp"
#include "communicator.hpp"
#include "distributed_operator.hpp"

namespace coatfft {

/// What make_distributed_operator built, and the report make_operator gives for the same method
/// (setup_seconds this rank's).
struct BuiltDistributedOperator {
  std::unique_ptr<DistributedOperator> op;
  OperatorReport report;
};

/// Whether `method` has a distributed operator: dcfft and frf-split, on either boundary (on a
/// periodic one both are the exact periodic kernel of the body's FRF, as serially).
bool runs_distributed(Method method);

/// The distributed operator of `body` on `grid`: on a periodic boundary the periodic kernel of
/// make_frf(body); on a free one Love's DC-FFT (dcfft, a homogeneous body only: check_love_body)
/// or frf-split's coefficients of make_frf(body). InvalidArgument for a method that does not run
/// distributed (runs_distributed), and as the operators' constructors.
BuiltDistributedOperator make_distributed_operator(const Communicator& comm, const Grid& grid,
                                                   const LayerStack& body,
                                                   const OperatorOptions& options);

/// The same for a body given by its FRF alone: periodic, or frf-split on a free boundary.
BuiltDistributedOperator make_distributed_operator(const Communicator& comm, const Grid& grid,
                                                   const Frf& frf, const OperatorOptions& options);

}  // namespace coatfft
