#pragma once
// The ranks (MPI processes) that share distributed fields, as the library's distributed parts use
// them: this rank, their number, and the reductions a solver needs, each the same on every rank.
// MPI stays out of the public headers: the communicator is an opaque handle. MpiSession
// (mpi_session.hpp) initialises MPI; world() and self() need it initialised.
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace coatfft {

class Communicator {
 public:
  struct Handle;  // the MPI_Comm (distributed/detail/mpi_handle.hpp)

  /// Every rank of the run (MPI_COMM_WORLD).
  static Communicator world();
  /// This rank alone (MPI_COMM_SELF): a one-rank run of the distributed code.
  static Communicator self();

  int rank() const;
  int size() const;
  /// The sums over the ranks of `values`, in place, in one reduction.
  void sum(std::span<double> values) const;
  double sum(double value) const;
  std::int64_t sum(std::int64_t value) const;
  double max(double value) const;
  /// Whether `value` holds on every rank.
  bool all(bool value) const;
  /// Every rank's `size` bytes at `mine`, in rank order, into `all` (size() * size bytes).
  void all_gather(const void* mine, std::size_t size, void* all) const;
  /// `text` as rank `root` has it, on every rank.
  void broadcast(std::string& text, int root = 0) const;
  void barrier() const;
  /// The ranks that share this rank's memory (its machine), itself included. Collective.
  int ranks_sharing_memory() const;

  const Handle& handle() const { return *handle_; }

 private:
  explicit Communicator(std::shared_ptr<const Handle> handle) : handle_(std::move(handle)) {}
  std::shared_ptr<const Handle> handle_;
};

}  // namespace coatfft
