// DcfftOperator against the direct multi-summation (DirectOperator) and against a plain,
// unpruned padded-FFT convolution written here with complex 2-D FFTW transforms; plus linearity,
// symmetry, plan reuse and input checks; the padding to fast FFT lengths on awkward grids.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "convolution/fft/detail/fftw_plan.hpp"
#include "convolution/kernels/influence_kernel.hpp"
#include "convolution/kernels/split_frf_kernel.hpp"
#include "convolution/operators/detail/dcfft_operator.hpp"
#include "convolution/operators/detail/direct_operator.hpp"
#include "core/error.hpp"
#include "core/norms.hpp"
#include "frf/frf.hpp"
#include "layers/layer_stack.hpp"

using coatfft::DcfftOperator;
using coatfft::DirectOperator;
using coatfft::Field;
using coatfft::Grid;
using coatfft::InfluenceKernel;

namespace {

Field random_field(std::ptrdiff_t nx, std::ptrdiff_t ny, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  Field f(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) f(i, j) = dist(rng);
  return f;
}

// An even kernel (every kernel coatfft makes is even) with random coefficients in every used slot
// of its quarter: no other structure, unlike Love's smooth decay.
InfluenceKernel random_kernel(const Grid& grid, unsigned seed) {
  return InfluenceKernel(grid, InfluenceKernel::Form::coefficients,
                         random_field(grid.nx() + 1, grid.ny() + 1, seed));
}

// Plain DC-FFT, independent of DcfftOperator's pruned real transforms: zero-pad p to (2nx, 2ny),
// full complex 2-D FFTs of p and of the wrapped kernel, multiply, inverse, divide by 4 nx ny, crop.
Field padded_fft_reference(const InfluenceKernel& kernel, const Field& p) {
  const std::ptrdiff_t nx = kernel.grid().nx();
  const std::ptrdiff_t ny = kernel.grid().ny();
  const std::ptrdiff_t mx = 2 * nx;
  const std::ptrdiff_t my = 2 * ny;
  const auto n = static_cast<std::size_t>(mx * my);
  const Field wrapped = kernel.wrapped();
  coatfft::FftwComplexBuffer pk(n);
  coatfft::FftwComplexBuffer kk(n);
  auto* pc = coatfft::as_complex(pk.data());
  auto* kc = coatfft::as_complex(kk.data());
  for (std::ptrdiff_t j = 0; j < my; ++j)
    for (std::ptrdiff_t i = 0; i < mx; ++i) {
      kc[j * mx + i] = wrapped(i, j);
      pc[j * mx + i] = (i < nx && j < ny) ? p(i, j) : 0.0;
    }
  const int dims[2] = {static_cast<int>(my), static_cast<int>(mx)};
  auto forward_p = coatfft::FftwPlan::create(
      1, [&] { return fftw_plan_dft(2, dims, pk.data(), pk.data(), FFTW_FORWARD, FFTW_ESTIMATE); });
  auto forward_k = coatfft::FftwPlan::create(
      1, [&] { return fftw_plan_dft(2, dims, kk.data(), kk.data(), FFTW_FORWARD, FFTW_ESTIMATE); });
  auto backward = coatfft::FftwPlan::create(1, [&] {
    return fftw_plan_dft(2, dims, pk.data(), pk.data(), FFTW_BACKWARD, FFTW_ESTIMATE);
  });
  forward_p.execute();
  forward_k.execute();
  for (std::size_t q = 0; q < n; ++q) pc[q] *= kc[q];
  backward.execute();
  Field u(nx, ny);
  for (std::ptrdiff_t j = 0; j < ny; ++j)
    for (std::ptrdiff_t i = 0; i < nx; ++i) u(i, j) = pc[j * mx + i].real() / double(n);
  return u;
}

struct Shape {
  std::ptrdiff_t nx, ny;
  double lx, ly;
};

const std::vector<Shape> shapes = {
    {1, 1, 1e-3, 1e-3},   {1, 7, 1e-3, 7e-3},   {7, 1, 7e-3, 1e-3},
    {2, 3, 2e-3, 3e-3},   {31, 33, 3e-3, 3e-3}, {32, 32, 1e-3, 1e-3},
    {64, 64, 2e-3, 2e-3}, {24, 40, 1e-3, 4e-3}, {17, 5, 3e-3, 0.2e-3}};

}  // namespace

TEST_CASE("DC-FFT equals direct summation and a plain padded FFT", "[convolution][dcfft]") {
  for (const auto& s : shapes) {
    const Grid grid(s.nx, s.ny, s.lx, s.ly);
    for (const bool love : {true, false}) {
      const InfluenceKernel kernel =
          love ? coatfft::love_kernel(grid, 2.2e11) : random_kernel(grid, 7u + unsigned(s.nx));
      const Field p =
          love ? Field(random_field(s.nx, s.ny, 11u).abs() * 1e9) : random_field(s.nx, s.ny, 13u);
      DcfftOperator dcfft(kernel);
      DirectOperator direct(kernel);
      const Field u = dcfft.apply(p);
      const Field u_direct = direct.apply(p);
      const Field u_plain = padded_fft_reference(kernel, p);
      INFO(s.nx << " x " << s.ny << (love ? " Love kernel" : " random kernel"));
      // FFT round-off grows like eps * log2(4 nx ny) relative to max|u| (< 1e-14 up to 64^2);
      // 1e-12 is the project's consistency tier and leaves room for random cancellations.
      CHECK(coatfft::rel_linf(u, u_direct) < 1e-12);
      // Both FFT pipelines round differently but equally little.
      CHECK(coatfft::rel_linf(u, u_plain) < 1e-13);
    }
  }
}

TEST_CASE("DC-FFT with measured plans and two threads gives the same result",
          "[convolution][dcfft]") {
  const Grid grid(48, 40, 1e-3, 1e-3);
  const auto kernel = random_kernel(grid, 3u);
  const Field p = random_field(48, 40, 5u);
  DcfftOperator a(kernel);
  DcfftOperator b(kernel, coatfft::Planning::measure, 2);
  CHECK(coatfft::rel_linf(b.apply(p), a.apply(p)) < 1e-13);
  CHECK(b.setup_seconds() >= 0.0);
}

TEST_CASE("DC-FFT splits its column blocks over two workers correctly", "[convolution][dcfft]") {
  // 2ny = 400 rows give blocks of a few columns, so hx = 101 columns make several blocks, shared
  // by two workers, the last one partial.
  const Grid grid(100, 200, 1e-3, 2e-3);
  for (const bool love : {true, false}) {
    const auto kernel = love ? coatfft::love_kernel(grid, 2e11) : random_kernel(grid, 17u);
    const Field p = random_field(100, 200, 6u);
    DcfftOperator op(kernel, coatfft::Planning::estimate, 2);
    CHECK(coatfft::rel_linf(op.apply(p), padded_fft_reference(kernel, p)) < 1e-13);
  }
}

TEST_CASE("DC-FFT is linear", "[convolution][dcfft]") {
  const Grid grid(31, 20, 1e-3, 1e-3);
  const auto kernel = random_kernel(grid, 21u);
  DcfftOperator op(kernel);
  const Field p = random_field(31, 20, 1u);
  const Field q = random_field(31, 20, 2u);
  const double alpha = 2.5;
  const double beta = -0.75;
  const Field lhs = op.apply(Field(alpha * p + beta * q));
  const Field rhs = alpha * op.apply(p) + beta * op.apply(q);
  // Each side carries ~1e-15 relative FFT round-off.
  CHECK(coatfft::rel_linf(lhs, rhs) < 1e-13);
}

TEST_CASE("DC-FFT reproduces the four-fold symmetry of a symmetric load", "[convolution][dcfft]") {
  for (const auto& [nx, ny] : {std::pair<std::ptrdiff_t, std::ptrdiff_t>{32, 32}, {33, 20}}) {
    const Grid grid(nx, ny, 2e-3, 2e-3 * double(ny) / double(nx));
    DcfftOperator op(coatfft::love_kernel(grid, 2.3e11));
    Field p(nx, ny);
    for (std::ptrdiff_t j = 0; j < ny; ++j)
      for (std::ptrdiff_t i = 0; i < nx; ++i) {
        const double r2 = (grid.x(i) * grid.x(i) + 2.0 * grid.y(j) * grid.y(j)) / 1e-6;
        p(i, j) = r2 < 1.0 ? 1e9 * std::sqrt(1.0 - r2) : 0.0;
      }
    // Exact mirror copy of the load (cell centres are symmetric only to rounding).
    p = 0.25 * (p + p.colwise().reverse() + p.rowwise().reverse() +
                p.colwise().reverse().rowwise().reverse());
    const Field u = op.apply(p);
    const double scale = u.abs().maxCoeff();
    INFO(nx << " x " << ny);
    // A wrong slot or an off-by-one shift breaks the symmetry at O(1); round-off gives ~1e-16.
    CHECK((u - u.colwise().reverse()).abs().maxCoeff() / scale < 1e-13);
    CHECK((u - u.rowwise().reverse()).abs().maxCoeff() / scale < 1e-13);
    CHECK(u.minCoeff() > 0.0);
  }
}

TEST_CASE("DC-FFT plans are reusable: applying twice gives identical results",
          "[convolution][dcfft]") {
  const Grid grid(20, 13, 1e-3, 1e-3);
  DcfftOperator op(random_kernel(grid, 9u));
  const Field p = random_field(20, 13, 4u);
  const Field first = op.apply(p);
  (void)op.apply(random_field(20, 13, 8u));
  const Field again = op.apply(p);
  CHECK((first == again).all());
}

TEST_CASE("DC-FFT pads awkward sizes to fast even lengths exactly", "[convolution][dcfft]") {
  // 2n = 254, 66, 22, 1022 (n = 127, 33, 11, 511) have a prime factor > 7; the padded lengths
  // are the smallest even 7-smooth lengths >= 2n - 1, and 2n where 2n already is one (7, 1, 5, 3).
  struct Case {
    std::ptrdiff_t nx, ny, mx, my;
  };
  for (const Case& c :
       {Case{127, 33, 256, 70}, Case{11, 7, 24, 14}, Case{1, 5, 2, 10}, Case{511, 3, 1024, 6}}) {
    const Grid grid(c.nx, c.ny, 1e-3 * double(c.nx), 1.3e-3 * double(c.ny));
    const InfluenceKernel kernel = coatfft::love_kernel(grid, 2.2e11);
    const Field p = random_field(c.nx, c.ny, 31u).abs() * 1e9;
    DcfftOperator dcfft(kernel);
    INFO(c.nx << " x " << c.ny);
    CHECK(dcfft.padded_nx() == c.mx);
    CHECK(dcfft.padded_ny() == c.my);
    // Positive pressures on a positive kernel: no cancellation, so both sides carry round-off
    // of order eps log2(mx my) relative to max|u| (measured 2e-16 to 7e-15 here); 1e-12 is the
    // project's consistency tier. A wrong slot or a wrap-around overlap would be O(1e-3) or more.
    CHECK(coatfft::rel_linf(dcfft.apply(p), DirectOperator(kernel).apply(p)) < 1e-12);
    // And on signed random coefficients and pressures (no structure that could hide a shift).
    const InfluenceKernel noise = random_kernel(grid, 5u + unsigned(c.nx));
    const Field q = random_field(c.nx, c.ny, 37u);
    CHECK(coatfft::rel_linf(DcfftOperator(noise, coatfft::Planning::estimate, 2).apply(q),
                            DirectOperator(noise).apply(q)) < 1e-12);
  }
}

TEST_CASE("DC-FFT keeps the exact 2n lattice for a kernel given as its spectrum",
          "[convolution][dcfft]") {
  // The spectrum form by its definition (influence_kernel.hpp): the cosine sum over all offsets
  // |di| < nx, |dj| < ny of the coefficients. On 11 x 7 the coefficient form pads to (24, 14),
  // the spectrum form must stay on (22, 14), and both must be the linear convolution.
  const Grid grid(11, 7, 1.1e-3, 0.7e-3);
  const InfluenceKernel love = coatfft::love_kernel(grid, 2.2e11);
  const double pi = std::acos(-1.0);
  Field spectrum = Field::Zero(12, 8);
  for (std::ptrdiff_t jy = 0; jy <= 7; ++jy)
    for (std::ptrdiff_t jx = 0; jx <= 11; ++jx)
      for (std::ptrdiff_t dj = -6; dj <= 6; ++dj)
        for (std::ptrdiff_t di = -10; di <= 10; ++di)
          spectrum(jx, jy) += love.at(di, dj) * std::cos(pi * double(jx * di) / 11.0) *
                              std::cos(pi * double(jy * dj) / 7.0);
  DcfftOperator from_spectrum(InfluenceKernel(grid, InfluenceKernel::Form::spectrum, spectrum));
  CHECK(from_spectrum.padded_nx() == 22);
  CHECK(from_spectrum.padded_ny() == 14);
  CHECK(DcfftOperator::padded_size(11, InfluenceKernel::Form::coefficients) == 24);
  const Field p = random_field(11, 7, 41u).abs() * 1e9;
  // The cosine sum rounds like the DCT (~1e-16 per term, 273 terms): well inside 1e-12.
  CHECK(coatfft::rel_linf(from_spectrum.apply(p), DirectOperator(love).apply(p)) < 1e-12);
}

TEST_CASE("DC-FFT of a coated body's split kernel on an odd grid equals direct summation",
          "[convolution][dcfft][split]") {
  // 37 x 23 cells (2n = 74, 46 are slow lengths; padded to 80 x 48) of a 1 um TiN-like coating
  // on steel, 10 um cells: the split kernel is a general coefficient kernel, not Love's.
  const Grid grid(37, 23, 370e-6, 230e-6);
  const coatfft::LayerStack body(
      {coatfft::Coating{coatfft::Material(600e9, 0.25), 1e-6, coatfft::Interface::bonded}},
      coatfft::Material(210e9, 0.3));
  const InfluenceKernel kernel = coatfft::split_frf_kernel(grid, *coatfft::make_frf(body));
  const Field p = random_field(37, 23, 43u).abs() * 1e9;
  DcfftOperator dcfft(kernel);
  CHECK(dcfft.padded_nx() == 80);
  CHECK(dcfft.padded_ny() == 48);
  // A positive load, as for Love's kernel: the same round-off tier (measured 3e-15).
  CHECK(coatfft::rel_linf(dcfft.apply(p), DirectOperator(kernel).apply(p)) < 1e-12);
}

TEST_CASE("Operators refuse a pressure of the wrong shape", "[convolution][bad_input]") {
  const Grid grid(8, 6, 1e-3, 1e-3);
  const auto kernel = coatfft::love_kernel(grid, 2e11);
  DcfftOperator dcfft(kernel);
  DirectOperator direct(kernel);
  Field u;
  CHECK_THROWS_AS(dcfft.apply(Field::Zero(6, 8), u), coatfft::InvalidArgument);
  CHECK_THROWS_WITH(dcfft.apply(Field::Zero(8, 5), u), Catch::Contains("(8, 5)"));
  CHECK_THROWS_AS(direct.apply(Field::Zero(7, 6), u), coatfft::InvalidArgument);
  Field p = Field::Ones(8, 6);
  CHECK_THROWS_AS(dcfft.apply(p, p), coatfft::InvalidArgument);
  CHECK_THROWS_AS(DcfftOperator(kernel, coatfft::Planning::estimate, 0), coatfft::InvalidArgument);
  CHECK(dcfft.name() == "dcfft");
  CHECK(direct.name() == "direct");
}

TEST_CASE("FFTW wisdom can be saved and loaded", "[convolution][fftw]") {
  const std::string path =
      (std::filesystem::temp_directory_path() / "coatfft_test_convolution_wisdom").string();
  {
    const Grid grid(16, 16, 1e-3, 1e-3);
    DcfftOperator op(coatfft::love_kernel(grid, 2e11), coatfft::Planning::measure);
  }
  coatfft::save_fftw_wisdom(path);
  CHECK(coatfft::load_fftw_wisdom(path));
  std::remove(path.c_str());
  CHECK_FALSE(coatfft::load_fftw_wisdom(path));
}

TEST_CASE("FFTW wisdom can be forgotten", "[convolution][fftw]") {
  // Wisdom's text is a header line (its checksums name the planner's set-up) and a line a plan.
  const auto lines = [] {
    const std::string text = coatfft::export_fftw_wisdom();
    return std::count(text.begin(), text.end(), '\n');
  };
  coatfft::forget_fftw_wisdom();
  const auto empty = lines();
  {
    const Grid grid(24, 24, 1e-3, 1e-3);
    DcfftOperator op(coatfft::love_kernel(grid, 2e11), coatfft::Planning::measure);
  }
  // The measured plans are wisdom; forgotten, the wisdom is as empty as before them.
  CHECK(lines() > empty);
  coatfft::forget_fftw_wisdom();
  CHECK(lines() == empty);
}
