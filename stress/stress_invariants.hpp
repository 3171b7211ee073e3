#pragma once
// Fields derived from the stress tensor at a point: von Mises' equivalent stress, the principal
// stresses and Tresca's maximum shear stress.
#include <array>

namespace coatfft {

/// A symmetric stress tensor [Pa] in stress.npy's order: xx, yy, zz, yz, xz, xy.
using StressVector = std::array<double, 6>;

/// sqrt(((s1 - s2)^2 + (s2 - s3)^2 + (s3 - s1)^2)/2) in components:
/// sqrt(((xx - yy)^2 + (yy - zz)^2 + (zz - xx)^2)/2 + 3 (yz^2 + xz^2 + xy^2)) [Pa].
double von_mises(const StressVector& s);

/// The principal stresses, largest first [Pa] (tension positive).
std::array<double, 3> principal_stresses(const StressVector& s);

/// The principal stresses, largest first [Pa], by the closed form (the roots of the
/// characteristic cubic, its simple root by Newton's method, no trigonometry): an order of
/// magnitude cheaper than principal_stresses, within about sqrt(eps) of the largest component
/// near a double root and far closer elsewhere. For screening many points (docs/stress.md,
/// "Summary maxima").
std::array<double, 3> closed_form_principal_stresses(const StressVector& s);

/// Tresca's maximum shear stress (s1 - s3)/2 [Pa].
double tresca(const StressVector& s);

}  // namespace coatfft
