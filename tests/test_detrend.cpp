// Detrending a measured topography (surfaces/detrend.hpp): a known plane plus a surface of zero
// mean and no tilt is that surface again after "plane", a known mean is removed by "mean", and
// the gap of a rigid flat is max(z) - z.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "surfaces/detrend.hpp"

using namespace coatfft;

TEST_CASE("detrend: a plane and a mean are removed, a surface without them is kept",
          "[surfaces][detrend]") {
  for (const Grid& g : {Grid(8, 6, 1e-3, 0.5e-3), Grid(7, 9, 2e-3, 3e-3)}) {
    // cos(2 pi x/lx) cos(2 pi y/ly) over the cell centres: zero mean, and orthogonal to x and y
    // (even in both) -- no plane to remove.
    Field s(g.nx(), g.ny());
    for (Eigen::Index j = 0; j < g.ny(); ++j)
      for (Eigen::Index i = 0; i < g.nx(); ++i)
        s(i, j) =
            1e-6 * std::cos(2 * M_PI * g.x(i) / g.lx()) * std::cos(2 * M_PI * g.y(j) / g.ly());
    Field tilted(g.nx(), g.ny());
    for (Eigen::Index j = 0; j < g.ny(); ++j)
      for (Eigen::Index i = 0; i < g.nx(); ++i)
        tilted(i, j) = s(i, j) + 3e-6 + 2e-3 * g.x(i) - 5e-4 * g.y(j);
    const double scale = 1e-6;
    CHECK((detrended(g, tilted, Detrend::plane) - s).abs().maxCoeff() < 1e-15 * scale * 1e3);
    CHECK((detrended(g, tilted, Detrend::none) - tilted).abs().maxCoeff() == 0.0);
    const Field m = detrended(g, s + 3e-6, Detrend::mean);
    CHECK((m - s).abs().maxCoeff() < 1e-12 * scale);
    CHECK(std::abs(detrended(g, tilted, Detrend::mean).mean()) < 1e-12 * scale);
  }
}

TEST_CASE("detrend: the gap of a flat, names, refusals", "[surfaces][detrend]") {
  const Grid g(4, 2, 1.0, 1.0);
  Field z(4, 2);
  z << 1, 2, 5, 3, -1, 0, 4, 2;
  const Field gap = gap_of_topography(z);
  CHECK(gap.minCoeff() == 0.0);
  CHECK(gap(1, 0) == 0.0);  // the highest peak (z = 5; Eigen fills row by row) touches first
  CHECK(gap(2, 0) == 6.0);  // the deepest valley, z = -1
  CHECK(detrend_from_name("plane", "[contact] detrend") == Detrend::plane);
  CHECK_THROWS_WITH(detrend_from_name("tilt", "[contact] detrend"),
                    Catch::Contains("[contact] detrend = \"tilt\" is not one of"));
  CHECK_THROWS_AS(detrended(g, Field::Zero(3, 2), Detrend::mean), InvalidArgument);
}
