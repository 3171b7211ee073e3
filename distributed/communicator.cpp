#include "distributed/communicator.hpp"

#include <mpi.h>

#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"

namespace coatfft {

namespace {

// An MPI call's error as an exception (MPI's default handler aborts first: this is the backstop
// for a handler set to return errors).
void check(int code, const char* what) {
  COATFFT_REQUIRE(code == MPI_SUCCESS, "MPI: ", what, " failed (error ", code, ")");
}

MPI_Comm comm_of(const Communicator& c) {
  return detail::mpi_comm(c);
}

// The handle of one of MPI's predefined communicators, once MPI is initialised.
std::shared_ptr<const Communicator::Handle> predefined(MPI_Comm comm) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  COATFFT_REQUIRE(initialised, "Communicator: MPI is not initialised (make an MpiSession first)");
  return std::make_shared<const Communicator::Handle>(Communicator::Handle{comm});
}

}  // namespace

Communicator Communicator::world() {
  return Communicator(predefined(MPI_COMM_WORLD));
}

Communicator Communicator::self() {
  return Communicator(predefined(MPI_COMM_SELF));
}

int Communicator::rank() const {
  int r = 0;
  check(MPI_Comm_rank(comm_of(*this), &r), "MPI_Comm_rank");
  return r;
}

int Communicator::size() const {
  int s = 0;
  check(MPI_Comm_size(comm_of(*this), &s), "MPI_Comm_size");
  return s;
}

void Communicator::sum(std::span<double> values) const {
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                      MPI_SUM, comm_of(*this)),
        "MPI_Allreduce");
}

double Communicator::sum(double value) const {
  sum(std::span<double>(&value, 1));
  return value;
}

std::int64_t Communicator::sum(std::int64_t value) const {
  check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT64_T, MPI_SUM, comm_of(*this)),
        "MPI_Allreduce");
  return value;
}

double Communicator::max(double value) const {
  check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, comm_of(*this)),
        "MPI_Allreduce");
  return value;
}

bool Communicator::all(bool value) const {
  int v = value ? 1 : 0;
  check(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_LAND, comm_of(*this)), "MPI_Allreduce");
  return v != 0;
}

void Communicator::all_gather(const void* mine, std::size_t size, void* all) const {
  check(MPI_Allgather(mine, static_cast<int>(size), MPI_BYTE, all, static_cast<int>(size), MPI_BYTE,
                      comm_of(*this)),
        "MPI_Allgather");
}

void Communicator::broadcast(std::string& text, int root) const {
  auto size = static_cast<std::int64_t>(text.size());
  check(MPI_Bcast(&size, 1, MPI_INT64_T, root, comm_of(*this)), "MPI_Bcast");
  text.resize(static_cast<std::size_t>(size));
  check(MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, root, comm_of(*this)),
        "MPI_Bcast");
}

void Communicator::barrier() const {
  check(MPI_Barrier(comm_of(*this)), "MPI_Barrier");
}

int Communicator::ranks_sharing_memory() const {
  MPI_Comm shared;
  check(MPI_Comm_split_type(comm_of(*this), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &shared),
        "MPI_Comm_split_type");
  int s = 0;
  const int status = MPI_Comm_size(shared, &s);
  MPI_Comm_free(&shared);
  check(status, "MPI_Comm_size");
  return s;
}

}  // namespace coatfft
