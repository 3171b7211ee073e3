// The distributed fields, transforms and operators (distributed/) against the serial library on
// the same problem, run by mpirun at 1, 2 and 3 ranks (3 gives uneven slabs): slabs tile the grid,
// the distributed periodic operator equals PeriodicOperator on a coated and a homogeneous body, the
// distributed DC-FFT equals DcfftOperator with Love's and frf-split's coefficients, contact solves
// equal the serial ones, a surface of a seed is the same at any rank count and equals
// self_affine_surface's.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

#include "contact/contact_solver.hpp"
#include "contact/detail/contact_patches.hpp"
#include "contact/detail/initial_pressure.hpp"
#include "contact/indenter.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/periodic_kernel.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/make_operator.hpp"
#include "convolution/operators/periodic_operator.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "distributed/communicator.hpp"
#include "distributed/detail/agreed_refusal.hpp"
#include "distributed/detail/communicator_ranks.hpp"
#include "distributed/distributed_contact.hpp"
#include "distributed/distributed_dcfft_operator.hpp"
#include "distributed/distributed_periodic_operator.hpp"
#include "distributed/make_distributed_operator.hpp"
#include "distributed/self_affine_slab.hpp"
#include "distributed/slab.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"
#include "surfaces/self_affine_surface.hpp"
#include "tests/test_materials.hpp"

using namespace coatfft;

namespace {

// This rank's rows of a whole field.
Field rows_of(const Field& whole, const Slab& s) {
  return whole.middleCols(s.y0, s.rows);
}

// max over the ranks of |a - b|, over max over the ranks of |b| (every rank gets the same).
double relative_difference(const Communicator& comm, const Field& a, const Field& b) {
  const double diff = a.size() ? (a - b).abs().maxCoeff() : 0.0;
  const double ref = b.size() ? b.abs().maxCoeff() : 0.0;
  return comm.max(diff) / comm.max(ref);
}

// A pressure field with random cells [Pa] (the same on every rank: the whole field).
Field random_pressure(const Grid& g, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1e9);
  Field p(g.nx(), g.ny());
  for (Eigen::Index n = 0; n < p.size(); ++n) p(n) = u(rng);
  return p;
}

// A distributed solve `b` against the serial solve `a` of the same problem: the same iterates up
// to the order of the sums (the ranks' partial sums added in rank order, the transforms' orders
// of operations), so the same iteration count, fields and numbers to 1e-10.
void check_same_solve(const Communicator& comm, const ContactResult& a, const ContactResult& b,
                      const Slab& s) {
  REQUIRE(a.converged);
  CHECK(b.converged);
  CHECK(b.iterations == a.iterations);
  CHECK(b.operator_applications == a.operator_applications);
  CHECK(relative_difference(comm, b.pressure, rows_of(a.pressure, s)) < 1e-10);
  CHECK(relative_difference(comm, b.displacement, rows_of(a.displacement, s)) < 1e-10);
  CHECK(comm.max(b.gap.size() ? (b.gap - rows_of(a.gap, s)).abs().maxCoeff() : 0.0) <
        1e-10 * a.displacement.abs().maxCoeff());
  CHECK(b.load == Approx(a.load).epsilon(1e-10));
  CHECK(*b.approach == Approx(*a.approach).epsilon(1e-10));
  CHECK(b.contact_area == a.contact_area);
  CHECK(b.max_pressure == Approx(a.max_pressure).epsilon(1e-10));
  CHECK(b.touches_boundary == a.touches_boundary);
}

}  // namespace

// A check each rank makes alone: its refusal reaches every rank (which would otherwise wait in
// the next collective step), named with the rank unless every rank refused alike.
TEST_CASE("a refusal on one rank is thrown on every rank, naming the rank") {
  const Communicator comm = Communicator::world();
  agreed_refusal(comm, [] {});
  const int last = comm.size() - 1;
  const std::string named =
      comm.size() == 1 ? "bad file" : "rank " + std::to_string(last) + ": bad file";
  const auto last_refuses = [&] {
    if (comm.rank() == last) throw InvalidArgument("bad file");
  };
  CHECK_THROWS_AS(agreed_refusal(comm, last_refuses), InvalidArgument);
  CHECK_THROWS_WITH(agreed_refusal(comm, last_refuses), named);
  CHECK_THROWS_WITH(agreed_refusal(comm, [] { throw InvalidArgument("the same"); }), "the same");
  // Another failure than a refusal of input stays one (exit status 1, not 2).
  try {
    agreed_refusal(comm, [&] {
      if (comm.rank() == last) throw std::runtime_error("broken");
    });
    FAIL("no exception");
  } catch (const InvalidArgument&) {
    FAIL("an internal failure became a refusal of input");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).ends_with("broken"));
  }
}

TEST_CASE("the ranks' slabs tile the grid's rows and its half spectrum's columns") {
  const Communicator comm = Communicator::world();
  for (auto [nx, ny] : {std::pair{44, 50}, {8, 6}, {64, 64}, {2, 2}}) {
    const Slab s = slab_of(comm, nx, ny);
    CHECK(comm.sum(static_cast<std::int64_t>(s.rows)) == ny);
    CHECK(comm.sum(static_cast<std::int64_t>(s.columns)) == nx / 2 + 1);
    // Contiguous, in rank order: this rank's first row is the count of the rows before it.
    const auto size = static_cast<std::size_t>(comm.size()),
               rank = static_cast<std::size_t>(comm.rank());
    std::vector<double> counts(2 * size, 0.0);
    counts[2 * rank] = static_cast<double>(s.rows);
    counts[2 * rank + 1] = static_cast<double>(s.columns);
    comm.sum(counts);
    double rows = 0, columns = 0;
    for (std::size_t r = 0; r < rank; ++r) {
      rows += counts[2 * r];
      columns += counts[2 * r + 1];
    }
    CHECK(comm.all(static_cast<double>(s.y0) == rows && static_cast<double>(s.kx0) == columns));
  }
}

TEST_CASE(
    "the distributed periodic operator equals the serial one on coated and homogeneous bodies") {
  const Communicator comm = Communicator::world();
  // 44 x 50 cells: 23 half-spectrum columns and 50 rows, uneven at 3 ranks (8, 8, 7 and 17, 17,
  // 16).
  const Grid grid(44, 50, 1e-3, 1.2e-3);
  const LayerStack coated({Coating{tin, 20e-6, Interface::bonded}}, steel);
  const LayerStack homogeneous({}, steel);
  for (const LayerStack* body : {&coated, &homogeneous}) {
    const auto frf = make_frf(*body);
    PeriodicOperator serial(grid, periodic_influence_kernel(grid, *frf), Method::frf_spectral);
    DistributedPeriodicOperator distributed(comm, grid, *frf);
    const Field p = random_pressure(grid, 7);
    const Field u = distributed.apply(rows_of(p, distributed.slab()));
    const Field reference = rows_of(serial.apply(p), distributed.slab());
    // Both are exact to rounding: the FFTs' orders of operations differ (a few ulp of the largest
    // displacement, 1e-13 leaves about 50 times that).
    const double d = relative_difference(comm, u, reference);
    CHECK(d < 1e-13);
  }
}

TEST_CASE("the distributed DC-FFT operator equals the serial one on the free surface") {
  const Communicator comm = Communicator::world();
  // 44 x 50 cells: 45 half-spectrum columns of the padded rows and 50 rows, uneven at 3 ranks;
  // 8 x 2: a rank without rows at 3 ranks.
  for (const Grid& grid : {Grid(44, 50, 1e-3, 1.2e-3), Grid(8, 2, 1e-3, 0.3e-3)}) {
    const double e_star = steel.plane_strain_modulus();
    DcfftOperator serial(love_kernel(grid, e_star));
    DistributedDcfftOperator distributed(comm, grid, e_star);
    const Field p = random_pressure(grid, 5);
    const Field u = distributed.apply(rows_of(p, distributed.slab()));
    const Field reference = rows_of(serial.apply(p), distributed.slab());
    // Both exact to rounding; the pruned transform's order of operations differs from the padded
    // 2-D one's (a few ulp of the largest displacement).
    CHECK(relative_difference(comm, u, reference) < 1e-13);
    CHECK_FALSE(distributed.periodic());
    CHECK(distributed.method() == Method::dcfft);
  }
}

// The distributed factory against the serial one: for every method and boundary that runs
// distributed, the operator make_operator builds for the same body and options (to rounding: the
// transforms' orders of operations), and the same report; the others refused by name.
TEST_CASE("make_distributed_operator builds make_operator's operator, or refuses by name") {
  const Communicator comm = Communicator::world();
  const Grid grid(24, 20, 1e-3, 0.8e-3);
  const LayerStack homogeneous({}, steel);
  const LayerStack coated({Coating{tin, 20e-6, Interface::bonded}}, steel);
  const Field p = random_pressure(grid, 7);
  for (const auto& [body, method, boundary] :
       {std::tuple{&homogeneous, Method::dcfft, Boundary::free},
        std::tuple{&coated, Method::frf_split, Boundary::free},
        std::tuple{&coated, Method::frf_split, Boundary::periodic},
        std::tuple{&homogeneous, Method::dcfft, Boundary::periodic}}) {
    OperatorOptions options;
    options.method = method;
    options.boundary = boundary;
    const BuiltOperator serial = make_operator(grid, *body, options);
    const BuiltDistributedOperator distributed =
        make_distributed_operator(comm, grid, *body, options);
    INFO(to_string(method) << (boundary == Boundary::periodic ? ", periodic" : ", free"));
    CHECK(distributed.report.method == serial.report.method);
    CHECK(distributed.report.frf == serial.report.frf);
    CHECK(distributed.op->periodic() == (boundary == Boundary::periodic));
    const Field u = distributed.op->apply(rows_of(p, distributed.op->slab()));
    CHECK(relative_difference(comm, u, rows_of(serial.op->apply(p), distributed.op->slab())) <
          1e-12);
  }
  OperatorOptions pipeline;
  pipeline.method = Method::frf_dcfft;
  CHECK_THROWS_WITH(make_distributed_operator(comm, grid, coated, pipeline),
                    Catch::Contains("\"frf-dcfft\" does not run distributed"));
  pipeline.method = Method::direct;
  CHECK_THROWS_WITH(make_distributed_operator(comm, grid, homogeneous, pipeline),
                    Catch::Contains("\"direct\" does not run distributed"));
  const OperatorOptions love;  // dcfft on a free boundary
  CHECK_THROWS_WITH(make_distributed_operator(comm, grid, coated, love),
                    Catch::Contains("homogeneous"));
  CHECK_THROWS_WITH(make_distributed_operator(comm, grid, *make_frf(coated), love),
                    Catch::Contains("a body given by its FRF takes \"frf-split\""));
}

TEST_CASE("the distributed frf-split operator equals the serial one on a coated free surface") {
  const Communicator comm = Communicator::world();
  struct Case {
    Grid grid;
    double thickness;
    double sigma = 0.0;  // the split's window; 0: automatic
  };
  // 44 x 50 cells of TiN 20 um: a lattice of 49 x 50 entries for the quarter's 45 x 51 (the
  // short range's reach is 32 sigma), each rank's lattice rows sent to other ranks' quarter rows;
  // 20 x 16: a lattice three times the quarter's rows; a window of 12 cells: the long range by its
  // stencil;
  // cells 200 times longer than wide: a wide axis, its 1-D lattice folded on every rank.
  for (const Case& c :
       {Case{Grid(44, 50, 1e-3, 1.2e-3), 20e-6}, Case{Grid(20, 16, 1e-3, 0.8e-3), 50e-6},
        Case{Grid(40, 36, 1e-3, 0.9e-3), 300e-6, 0.3e-3},
        Case{Grid(6, 40, 1.2e-3, 0.04e-3), 5e-6}}) {
    const auto frf = make_frf(LayerStack({Coating{tin, c.thickness, Interface::bonded}}, steel));
    SplitKernelOptions options;
    options.sigma = c.sigma;
    SplitKernelReport report;
    DcfftOperator serial(split_frf_kernel(c.grid, *frf, options, &report));
    DistributedDcfftOperator distributed(comm, c.grid, *frf, options);
    CHECK(distributed.method() == Method::frf_split);
    const Field p = random_pressure(c.grid, 5);
    const Field u = distributed.apply(rows_of(p, distributed.slab()));
    const Field reference = rows_of(serial.apply(p), distributed.slab());
    INFO(c.grid.nx() << " x " << c.grid.ny() << ", h = " << c.thickness << ": cell rule "
                     << report.cell_rule << ", wide " << report.wide_x << report.wide_y);
    // The same coefficients to rounding (the lattice's transforms' orders of operations differ).
    CHECK(relative_difference(comm, u, reference) < 1e-13);
  }
}

namespace {

// A paraboloid (R = 5 mm) pressed into the free surface of the grid of `op` (1 mm x 0.9 mm) by
// `serial_op` and by `op` alike, under load and approach control (a contact radius of about 0.25
// mm, a quarter of the domain): the same solve. Returns the distributed solver.
std::unique_ptr<ContactSolver> check_free_paraboloid(const Communicator& comm,
                                                     SurfaceOperator& serial_op,
                                                     DistributedOperator& op) {
  const double radius = 5e-3, e_star = steel.plane_strain_modulus();
  const Field h = height(op.grid(), Paraboloid{radius});
  const Slab& s = op.slab();
  ContactOptions options;
  options.nested_start = false;  // one patch: the serial solve takes none either
  options.compute_approach = true;
  ContactSolver serial(serial_op, options);
  auto distributed = distributed_contact_solver(op, options);
  const double load = 4.0 * e_star * std::pow(0.25e-3, 3) / (3.0 * radius);  // Hertz, a = 0.25 mm
  for (const ContactControl control : {ContactControl::load, ContactControl::approach}) {
    const double value = control == ContactControl::load ? load : 0.25e-3 * 0.25e-3 / radius;
    check_same_solve(comm, serial.solve(h, control, value),
                     distributed->solve(rows_of(h, s), control, value), s);
  }
  return distributed;
}

}  // namespace

TEST_CASE("a distributed free Hertz contact equals the serial solve") {
  const Communicator comm = Communicator::world();
  const Grid grid(48, 42, 1e-3, 0.9e-3);
  const double e_star = steel.plane_strain_modulus();
  DcfftOperator serial_op(love_kernel(grid, e_star));
  DistributedDcfftOperator op(comm, grid, e_star);
  const auto distributed = check_free_paraboloid(comm, serial_op, op);
  // A contact reaching the domain's edge is seen by the rank that holds the border rows.
  const Field h = height(grid, Paraboloid{5e-3});
  const double load = 4.0 * e_star * std::pow(0.25e-3, 3) / (3.0 * 5e-3);
  CHECK(
      distributed->solve(rows_of(h, op.slab()), ContactControl::load, 50 * load).touches_boundary);
}

TEST_CASE("a distributed free contact of a coated body equals the serial solve") {
  const Communicator comm = Communicator::world();
  // TiN 20 um on steel, by frf-split's coefficients.
  const Grid grid(48, 42, 1e-3, 0.9e-3);
  const auto frf = make_frf(LayerStack({Coating{tin, 20e-6, Interface::bonded}}, steel));
  DcfftOperator serial_op(split_frf_kernel(grid, *frf));
  DistributedDcfftOperator op(comm, grid, *frf);
  check_free_paraboloid(comm, serial_op, op);
}

TEST_CASE("the distributed periodic operator refuses a bad pressure on every rank together") {
  const Communicator comm = Communicator::world();
  const Grid grid(16, 12, 1e-3, 1e-3);
  const auto frf = make_frf(LayerStack({}, steel));
  DistributedPeriodicOperator op(comm, grid, *frf);
  // A value that is not finite (NaN, +-Inf) in one cell of the last row or of the first (the
  // other ranks' pressures are fine): every rank refuses it, although each checks its own
  // displacement only.
  Field u;
  const Slab& s = op.slab();
  for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL})
    for (const bool last : {true, false}) {
      Field p = Field::Constant(s.nx, s.rows, 1e6);
      if (last && s.rows > 0 && s.y0 + s.rows == grid.ny()) p(5, s.rows - 1) = bad;
      if (!last && s.rows > 0 && s.y0 == 0) p(11, 0) = bad;
      CHECK_THROWS_WITH(op.apply(p, u), Catch::Contains("not finite"));
    }
  CHECK_NOTHROW(op.apply(Field::Constant(s.nx, s.rows, 1e6), u));
  // A pressure of the wrong shape on rank 0 only.
  Field q = op.slab().field();
  if (comm.rank() == 0) q.resize(3, 3);
  CHECK_THROWS_AS(op.apply(q, u), InvalidArgument);
}

TEST_CASE(
    "a self-affine surface of a seed is the same at any rank count and equals the serial one") {
  const Communicator comm = Communicator::world();
  const Grid grid(48, 46, 1e-3, 1e-3);
  for (bool by_slope : {false, true}) {
    SelfAffineSpec spec;
    spec.hurst = 0.7;
    spec.seed = 12345;
    if (by_slope) {
      spec.rms_slope = 0.1;
    } else {
      spec.rms_height = 1e-6;
    }
    const Field slab = self_affine_slab(comm, grid, spec);
    // One rank alone makes the whole surface by the same steps: this rank's rows of it.
    const Slab s = slab_of(comm, grid.nx(), grid.ny());
    const Field alone = rows_of(self_affine_slab(Communicator::self(), grid, spec), s);
    CHECK(relative_difference(comm, slab, alone) == 0.0);
    // The serial generator takes the same 1-D transforms (surfaces/self_affine_surface.cpp).
    const Field whole = self_affine_surface(grid, spec);
    CHECK(relative_difference(comm, slab, rows_of(whole, s)) == 0.0);
    // The distributed spectral rms slope: Parseval over each rank's columns, summed.
    CHECK(spectral_rms_slope(comm, grid, slab) ==
          Approx(spectral_rms_slope(grid, whole)).epsilon(1e-13));
  }
}

namespace {

// A rough surface of `seed` pressed into TiN 5 um on steel to about 10 % contact, whole on every
// rank (the reference) and in slabs, with its serial and distributed periodic operators.
struct RoughPeriodicCase {
  Grid grid;
  Field h;
  std::unique_ptr<Frf> frf = make_frf(LayerStack({Coating{tin, 5e-6, Interface::bonded}}, steel));
  PeriodicOperator serial_op;
  DistributedPeriodicOperator op;
  RoughPeriodicCase(const Communicator& comm, const Grid& g, unsigned seed)
      : grid(g),
        h(heights(g, seed)),
        serial_op(g, periodic_influence_kernel(g, *frf), Method::frf_split),
        op(comm, g, *frf) {}
  static Field heights(const Grid& g, unsigned seed) {
    SelfAffineSpec spec;
    spec.hurst = 0.8;
    spec.rms_slope = 0.05;
    spec.seed = seed;
    const Field z = self_affine_surface(g, spec);
    return z.maxCoeff() - z;
  }
  // Serial and distributed solves under load and approach control: the same solve, and the same
  // coarse applications (none without the nested start).
  void check_solves(const Communicator& comm, bool nested) {
    ContactOptions options;
    options.nested_start = nested;
    options.compute_approach = true;
    ContactSolver serial(serial_op, options);
    const auto distributed = distributed_contact_solver(op, options);
    const double load = 0.045 * steel.plane_strain_modulus() * 0.05 * grid.lx() * grid.ly();
    const double approach = h.mean() - 0.6 * (h.mean() - h.minCoeff());
    for (const ContactControl control : {ContactControl::load, ContactControl::approach}) {
      const double value = control == ContactControl::load ? load : approach;
      const ContactResult a = serial.solve(h, control, value);
      const ContactResult b = distributed->solve(rows_of(h, op.slab()), control, value);
      CHECK((a.coarse_applications > 0) == nested);
      CHECK(b.coarse_applications == a.coarse_applications);
      check_same_solve(comm, a, b, op.slab());
      CHECK(b.touches_boundary == false);  // a periodic surface has no edge
    }
  }
};

}  // namespace

TEST_CASE("a distributed periodic rough contact of a coated body equals the serial solve") {
  // 50 rows: no coarse grid pairs them at 3 ranks; both solves start from the Hertzian start.
  RoughPeriodicCase(Communicator::world(), Grid(64, 50, 1e-3, 0.8e-3), 3)
      .check_solves(Communicator::world(), false);
}

TEST_CASE("the distributed level of the heights is the serial quantile, ties and signs alike") {
  const Communicator comm = Communicator::world();
  // Fields with ties (values on a coarse lattice), both signs, -0 and +0, and grids whose rows
  // leave a rank empty at 3 ranks (2 rows); each rank holds its rows of the same whole field.
  std::mt19937_64 rng(11);
  for (auto [nx, ny] : {std::pair{16, 12}, {7, 2}, {33, 5}}) {
    for (double lattice : {0.0, 0.25}) {
      Field h(nx, ny);
      for (Eigen::Index n = 0; n < h.size(); ++n) {
        const double v = -1.0 + 2.0 * static_cast<double>(rng() >> 11) * 0x1.0p-53;
        h(n) = lattice > 0 ? lattice * std::round(v / lattice) : v;
      }
      h(0) = -0.0;
      const Slab s = slab_of(comm, nx, ny);
      const detail::CommunicatorRanks ranks(comm, s);
      const Field mine = rows_of(h, s);
      for (double share : {0.0, 0.1, 0.25, 0.5, 0.99}) {
        const double serial = detail::level_below(h, share);
        const double distributed = detail::level_below(mine, share, &ranks);
        CHECK(comm.all(distributed == serial));
      }
    }
  }
}

TEST_CASE("the distributed count of contact patches is the serial one") {
  const Communicator comm = Communicator::world();
  // Random masks from sparse to dense (patches crossing the slabs' borders, wrapping both ways,
  // or spanning every rank), free and periodic; grids whose rows leave a rank empty at 3 ranks.
  std::mt19937_64 rng(17);
  for (auto [nx, ny] : {std::pair{40, 30}, {9, 2}, {24, 7}}) {
    const Slab s = slab_of(comm, nx, ny);
    const detail::CommunicatorRanks ranks(comm, s);
    for (double density : {0.1, 0.4, 0.6, 0.9}) {
      detail::CellMask cells(nx, ny);
      for (Eigen::Index n = 0; n < cells.size(); ++n)
        cells(n) = static_cast<double>(rng() >> 11) * 0x1.0p-53 < density;
      const detail::CellMask mine = cells.middleCols(s.y0, s.rows);
      for (const bool periodic : {false, true}) {
        const int serial = detail::count_patches(cells, periodic);
        CHECK(comm.all(detail::count_patches(mine, periodic, &ranks) == serial));
      }
    }
  }
}

TEST_CASE("a distributed periodic rough contact takes the serial nested start") {
  const Communicator comm = Communicator::world();
  // 128 x 384 cells: the nested start's coarse grid (64 x 192) pairs each rank's rows at 1, 2 and
  // 3 ranks (FFTW's slabs of 384, 192 or 128 rows and of their halves), and is the coarsest (its
  // side is under twice 64).
  RoughPeriodicCase rough(comm, Grid(128, 384, 1e-3, 3e-3), 7);
  rough.check_solves(comm, true);
  // The Galerkin coarse operator of the ranks is the serial one's, row for row.
  const std::unique_ptr<SurfaceOperator> coarse = rough.op.coarsened();
  const std::unique_ptr<SurfaceOperator> serial_coarse = rough.serial_op.coarsened();
  REQUIRE(coarse);
  const auto& coarse_slab = dynamic_cast<const DistributedOperator&>(*coarse).slab();
  const Field p = random_pressure(serial_coarse->grid(), 5);
  CHECK(relative_difference(comm, coarse->apply(rows_of(p, coarse_slab)),
                            rows_of(serial_coarse->apply(p), coarse_slab)) < 1e-12);
}

TEST_CASE("a distributed contact solve stops on every rank when one rank is interrupted") {
  const Communicator comm = Communicator::world();
  const Grid grid(32, 30, 1e-3, 1e-3);
  SelfAffineSpec spec;
  spec.rms_slope = 0.05;
  const Field z = self_affine_surface(grid, spec);
  const auto frf = make_frf(LayerStack({}, steel));
  DistributedPeriodicOperator op(comm, grid, *frf);
  const auto solver = distributed_contact_solver(op);
  // Ctrl-C seen by the last rank only (a hook asked at every check): every rank throws, none is
  // left waiting in a sum.
  std::optional<ScopedInterruptHook> hook;
  if (comm.rank() == comm.size() - 1)
    hook.emplace([] { return true; }, std::chrono::milliseconds(0));
  const double load = 0.01 * steel.plane_strain_modulus() * 0.05 * grid.lx() * grid.ly();
  CHECK_THROWS_AS(solver->solve_load(rows_of(z.maxCoeff() - z, op.slab()), load), Interrupted);
}
