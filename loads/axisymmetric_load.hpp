#pragma once
// The axisymmetric load shapes of the references and the automatic choices: a Hertz pressure and
// a uniform disk, with their 2-D Fourier transforms (docs/theory.md §1.4, §1.5).
namespace coatfft {

/// Axisymmetric pressures on the disk r < a: Hertz p0 sqrt(1 - r^2/a^2), or uniform p.
enum class AxisymmetricLoad { hertz, uniform_disk };

/// The dimensionless shape Phi(s), s = k a, of the load's transform P^(k) = 2 pi amplitude a^2
/// Phi(ka): Hertz j1(s)/s, uniform disk J1(s)/s (series below s = 1e-4).
double axisymmetric_load_shape(AxisymmetricLoad load, double s);

/// 2-D Fourier transform P^(k) [N] of the load at k >= 0 [rad/m]: Hertz 2 pi p0 a^2 j1(ka)/(ka),
/// uniform disk 2 pi p a^2 J1(ka)/(ka). amplitude = p0 or p [Pa], a = load radius [m].
double axisymmetric_load_transform(AxisymmetricLoad load, double amplitude, double a, double k);

}  // namespace coatfft
