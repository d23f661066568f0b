// Mass properties of primitive shapes by analytic formula (handbook values, e.g. the tables of
// Meriam & Kraige or Wikipedia's "List of moments of inertia"), given a total mass or a density.
//
// Each shape is built in its natural frame: centre of mass at the origin, symmetry axis along z,
// edges along x, y, z. The returned SpatialInertia is expressed in that frame (com = 0 except for the
// tetrahedron, which is given by its vertices); place it with SpatialInertia::transformed(X_AB).
// Density is per unit volume [kg/m^3] for solids, per unit area [kg/m^2] for shells, disks and
// plates, per unit length [kg/m] for rods: each function says which. Lengths in [m].
#pragma once
#include <Eigen/Core>

#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace rigiddyn {

struct Mass {
  double value;  // total mass [kg]
};
struct Density {
  double value;  // [kg/m^3], [kg/m^2] or [kg/m], per the shape
};

// Either a total mass or a density; mass_of(measure) gives the mass of a shape of that volume, area
// or length. Throws std::invalid_argument unless the value is finite and > 0.
class MassOrDensity {
 public:
  MassOrDensity(Mass mass);        // NOLINT(google-explicit-constructor): solid_sphere(r, Mass{2})
  MassOrDensity(Density density);  // NOLINT(google-explicit-constructor)
  double mass_of(double measure) const { return is_mass_ ? value_ : value_ * measure; }

 private:
  double value_;
  bool is_mass_;
};

// Solid sphere of radius r: I = 2/5 m r^2 1. Volume density.
SpatialInertia solid_sphere(double radius, MassOrDensity md);
// Thick spherical shell, outer radius R > inner radius r >= 0: I = 2/5 m (R^5 - r^5)/(R^3 - r^3) 1.
// Volume density.
SpatialInertia hollow_sphere(double outer_radius, double inner_radius, MassOrDensity md);
// Thin spherical shell (surface) of radius r: I = 2/3 m r^2 1. Area density.
SpatialInertia spherical_shell(double radius, MassOrDensity md);
// Solid box with edges (a, b, c) along x, y, z: I = m/12 diag(b^2+c^2, a^2+c^2, a^2+b^2). Volume density.
SpatialInertia solid_box(const Eigen::Vector3d& size, MassOrDensity md);
// Closed thin-walled box (its six faces) with edges (a, b, c) along x, y, z:
// I_xx = 2 s [bc (b^2+c^2)/12 + ac (c^2/12 + b^2/4) + ab (b^2/12 + c^2/4)] (s the area density) and
// cyclically. Area density.
SpatialInertia box_shell(const Eigen::Vector3d& size, MassOrDensity md);
// Solid cylinder, radius r, height h, axis z: I_zz = m r^2/2, I_xx = I_yy = m (3 r^2 + h^2)/12.
// Volume density.
SpatialInertia solid_cylinder(double radius, double height, MassOrDensity md);
// Thick tube, outer radius R > inner radius r >= 0, height h, axis z, open ends:
// I_zz = m (R^2 + r^2)/2, I_xx = I_yy = m (3 (R^2 + r^2) + h^2)/12. Volume density.
SpatialInertia hollow_cylinder(double outer_radius, double inner_radius, double height, MassOrDensity md);
// Thin rod of length L along z: I_xx = I_yy = m L^2/12, I_zz = 0. Length density.
SpatialInertia thin_rod(double length, MassOrDensity md);
// Thin disk of radius r in the xy plane: I_xx = I_yy = m r^2/4, I_zz = m r^2/2. Area density.
SpatialInertia thin_disk(double radius, MassOrDensity md);
// Thin rectangular plate with edges (a, b) along x, y in the xy plane:
// I = m/12 diag(b^2, a^2, a^2 + b^2). Area density.
SpatialInertia thin_plate(double size_x, double size_y, MassOrDensity md);
// Solid right circular cone, base radius r, height h, axis z, apex at z = +3h/4 and base at z = -h/4
// (centre of mass at the origin): I_zz = 3/10 m r^2, I_xx = I_yy = m (3/20 r^2 + 3/80 h^2). Volume density.
SpatialInertia solid_cone(double radius, double height, MassOrDensity md);
// Solid ellipsoid with semi-axes (a, b, c) along x, y, z: I = m/5 diag(b^2+c^2, a^2+c^2, a^2+b^2).
// Volume density.
SpatialInertia solid_ellipsoid(const Eigen::Vector3d& semi_axes, MassOrDensity md);
// Solid capsule: a cylinder of radius r and length h along z capped by two hemispheres of radius r
// (total length h + 2r). With m_c = rho pi r^2 h and m_h = rho 2/3 pi r^3 (each hemisphere):
// I_zz = m_c r^2/2 + 4/5 m_h r^2, I_xx = I_yy = m_c (h^2/12 + r^2/4) + 2 m_h (2/5 r^2 + h^2/4 + 3/8 h r).
// Volume density (a given mass is split in the same proportions). h >= 0.
SpatialInertia solid_capsule(double radius, double length, MassOrDensity md);
// Solid tetrahedron with the given vertices [m] (any order), expressed in their frame:
// com = mean of the vertices, I_C from the exact second moment
// integral x x^T dV = V/20 (sum v_i v_i^T + s s^T), s = sum v_i. Volume density.
SpatialInertia solid_tetrahedron(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1, const Eigen::Vector3d& v2,
                                 const Eigen::Vector3d& v3, MassOrDensity md);

}  // namespace rigiddyn
