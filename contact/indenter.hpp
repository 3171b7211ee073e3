#pragma once
// Indenter shapes: the initial separation h(x, y) [m] between a rigid indenter and the flat surface
// of the body before loading, sampled at the cell centres of a Grid (docs/conventions.md). Every
// shape is centred on the origin with its lowest point at h = 0, so the rigid-body approach delta
// [m] of a contact solve is measured from first touch. The body's elasticity enters through the
// SurfaceOperator only; for two elastic bodies use the composite modulus (validation/
// hertz_contact.hpp) in the operator and the composite curvature in the shape.
#include <optional>
#include <variant>

#include "../core/grid.hpp"
#include "../core/types.hpp"

namespace coatfft {

/// Exact sphere of radius R [m]: h = R - sqrt(R^2 - r^2). Refuses a grid whose farthest cell centre
/// lies at r > R (the sphere has no surface there).
struct Sphere {
  double radius;
};

/// Paraboloid of revolution with tip radius R [m]: h = r^2 / (2 R), the Hertz (small-slope) form.
struct Paraboloid {
  double radius;
};

/// Cylinder (roller) with its axis along x: cross-section radius R [m], a straight part of length
/// L [m] on |x| <= L/2, and rounded ends of profile radius Re [m] beyond it. Small-slope form
///   h = y^2 / (2 R) + (max(|x| - L/2, 0))^2 / (2 Re),
/// i.e. a parabolic cylinder whose ends are blended by parabolic crowns of radius Re (the gap and
/// its slope are continuous at |x| = L/2). L = 0 gives an ellipsoid-like body with radii R and Re.
struct Cylinder {
  double radius;
  double flat_length;
  double end_radius;
};

/// Flat circular punch of radius a [m] with a rounded edge of radius rho [m] (> 0):
///   h = 0 for r <= a,   h = (r - a)^2 / (2 rho) for r > a   (small-slope edge blend).
/// As rho -> 0 it tends to the sharp punch of Boussinesq (W = 2 a E* delta).
struct FlatPunch {
  double radius;
  double edge_radius;
};

/// A measured or generated height map [m] of shape (nx, ny) on the solve's grid (same layout as
/// Field). Used as given: no shift to min(h) = 0, so the approach is measured from h = 0.
struct HeightMap {
  Field heights;
};

/// Any of the indenters above (for scene files and the CLI).
using Indenter = std::variant<Sphere, Paraboloid, Cylinder, FlatPunch, HeightMap>;

/// Initial separation h [m] at the cell centres of `grid` (Field of shape (nx, ny)). Throws
/// InvalidArgument for non-finite or non-positive radii/lengths, for a Sphere smaller than the
/// domain's half-diagonal, and for a HeightMap of the wrong shape or with a non-finite entry.
Field height(const Grid& grid, const Sphere& sphere);
Field height(const Grid& grid, const Paraboloid& paraboloid);
Field height(const Grid& grid, const Cylinder& cylinder);
Field height(const Grid& grid, const FlatPunch& punch);
Field height(const Grid& grid, const HeightMap& map);
Field height(const Grid& grid, const Indenter& indenter);
/// height(grid, indenter), but a HeightMap's heights are moved out (the map is left empty, and
/// checked as height() checks it): a large map is not held twice.
Field take_height(const Grid& grid, Indenter& indenter);
/// The rows y0 <= j < y0 + rows of height(grid, indenter): a Field (nx, rows), the part of a
/// distributed solve's slab (distributed/slab.hpp) sampled without the whole field (a HeightMap's
/// rows are taken from the map it holds). Throws as height(), and for rows outside the grid.
Field height_rows(const Grid& grid, const Indenter& indenter, std::ptrdiff_t y0,
                  std::ptrdiff_t rows);

/// The checks of height() without sampling anything (no grid-sized allocation): for a reader of
/// user input that must refuse a bad shape before it knows whether the grid fits in memory.
void check_indenter(const Grid& grid, const Sphere& sphere);
void check_indenter(const Grid& grid, const Paraboloid& paraboloid);
void check_indenter(const Grid& grid, const Cylinder& cylinder);
void check_indenter(const Grid& grid, const FlatPunch& punch);
void check_indenter(const Grid& grid, const HeightMap& map);
void check_indenter(const Grid& grid, const Indenter& indenter);

/// True when the shape is a body of revolution about the z axis, so that the contact it makes on
/// a layered (laterally uniform) body is a disk and has a contact radius: Sphere, Paraboloid,
/// FlatPunch, and a Cylinder with no straight part and equal radii (L = 0, Re = R: the
/// paraboloid). False for any other Cylinder and for a HeightMap, whose contact has only the
/// equivalent radius sqrt(A / pi).
bool is_axisymmetric(const Indenter& indenter);

/// The radius of a sphere or paraboloid (the shapes Hertz's and Maugis' solutions describe);
/// none for the other indenters.
std::optional<double> ball_radius(const Indenter& indenter);

}  // namespace coatfft
