#include "rigiddyn/inertia/primitives.hpp"

#include <Eigen/LU>

#include <cmath>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {

constexpr double pi = 3.14159265358979323846;

// A body of `measure` (volume, area or length) whose inertia about its centre of mass (the origin)
// is `per_mass` times its mass.
SpatialInertia centred(MassOrDensity md, double measure, const Eigen::Vector3d& per_mass_diagonal) {
  const double m = md.mass_of(measure);
  return SpatialInertia(m, Eigen::Vector3d::Zero(), (m * per_mass_diagonal).asDiagonal().toDenseMatrix());
}

void require_size(const Eigen::Vector3d& size, const char* name) {
  if (!(size.allFinite() && size.minCoeff() > 0.0)) throw_invalid(name, "finite values > 0", size);
}

}  // namespace

MassOrDensity::MassOrDensity(Mass mass) : value_(mass.value), is_mass_(true) { require_positive(value_, "mass"); }
MassOrDensity::MassOrDensity(Density density) : value_(density.value), is_mass_(false) {
  require_positive(value_, "density");
}

SpatialInertia solid_sphere(double radius, MassOrDensity md) {
  require_positive(radius, "radius");
  const double r2 = radius * radius;
  return centred(md, 4.0 / 3.0 * pi * r2 * radius, Eigen::Vector3d::Constant(0.4 * r2));
}

SpatialInertia hollow_sphere(double outer_radius, double inner_radius, MassOrDensity md) {
  require_positive(outer_radius, "outer_radius");
  if (!(std::isfinite(inner_radius) && inner_radius >= 0.0 && inner_radius < outer_radius)) {
    throw_invalid("inner_radius", "a number in [0, outer_radius = " + format_value(outer_radius) + ")", inner_radius);
  }
  const double R = outer_radius, r = inner_radius;
  const double R3 = R * R * R, r3 = r * r * r;
  const double k = 0.4 * (R3 * R * R - r3 * r * r) / (R3 - r3);
  return centred(md, 4.0 / 3.0 * pi * (R3 - r3), Eigen::Vector3d::Constant(k));
}

SpatialInertia spherical_shell(double radius, MassOrDensity md) {
  require_positive(radius, "radius");
  const double r2 = radius * radius;
  return centred(md, 4.0 * pi * r2, Eigen::Vector3d::Constant(2.0 / 3.0 * r2));
}

SpatialInertia solid_box(const Eigen::Vector3d& size, MassOrDensity md) {
  require_size(size, "size");
  const Eigen::Vector3d s2 = size.cwiseAbs2();
  return centred(md, size.prod(), Eigen::Vector3d(s2(1) + s2(2), s2(0) + s2(2), s2(0) + s2(1)) / 12.0);
}

SpatialInertia box_shell(const Eigen::Vector3d& size, MassOrDensity md) {
  require_size(size, "size");
  const double area = 2.0 * (size(0) * size(1) + size(1) * size(2) + size(2) * size(0));
  // about axis i with the other edges (b, c): the two faces normal to i (area bc, own inertia
  // (b^2+c^2)/12 per area), the two normal to j (area ac at distance b/2) and to k (area ab at c/2)
  Eigen::Vector3d per_area;
  for (int i = 0; i < 3; ++i) {
    const double a = size(i), b = size((i + 1) % 3), c = size((i + 2) % 3);
    per_area(i) = 2.0 * (b * c * (b * b + c * c) / 12.0 + a * c * (c * c / 12.0 + b * b / 4.0) +
                         a * b * (b * b / 12.0 + c * c / 4.0));
  }
  return centred(md, area, per_area / area);
}

SpatialInertia solid_cylinder(double radius, double height, MassOrDensity md) {
  require_positive(radius, "radius");
  require_positive(height, "height");
  const double r2 = radius * radius, h2 = height * height;
  const double transverse = (3.0 * r2 + h2) / 12.0;
  return centred(md, pi * r2 * height, Eigen::Vector3d(transverse, transverse, 0.5 * r2));
}

SpatialInertia hollow_cylinder(double outer_radius, double inner_radius, double height, MassOrDensity md) {
  require_positive(outer_radius, "outer_radius");
  require_positive(height, "height");
  if (!(std::isfinite(inner_radius) && inner_radius >= 0.0 && inner_radius < outer_radius)) {
    throw_invalid("inner_radius", "a number in [0, outer_radius = " + format_value(outer_radius) + ")", inner_radius);
  }
  const double sum2 = outer_radius * outer_radius + inner_radius * inner_radius;
  const double diff2 = outer_radius * outer_radius - inner_radius * inner_radius;
  const double transverse = (3.0 * sum2 + height * height) / 12.0;
  return centred(md, pi * diff2 * height, Eigen::Vector3d(transverse, transverse, 0.5 * sum2));
}

SpatialInertia thin_rod(double length, MassOrDensity md) {
  require_positive(length, "length");
  const double transverse = length * length / 12.0;
  return centred(md, length, Eigen::Vector3d(transverse, transverse, 0.0));
}

SpatialInertia thin_disk(double radius, MassOrDensity md) {
  require_positive(radius, "radius");
  const double r2 = radius * radius;
  return centred(md, pi * r2, Eigen::Vector3d(0.25 * r2, 0.25 * r2, 0.5 * r2));
}

SpatialInertia thin_plate(double size_x, double size_y, MassOrDensity md) {
  require_positive(size_x, "size_x");
  require_positive(size_y, "size_y");
  const double a2 = size_x * size_x, b2 = size_y * size_y;
  return centred(md, size_x * size_y, Eigen::Vector3d(b2, a2, a2 + b2) / 12.0);
}

SpatialInertia solid_cone(double radius, double height, MassOrDensity md) {
  require_positive(radius, "radius");
  require_positive(height, "height");
  const double r2 = radius * radius, h2 = height * height;
  const double transverse = 3.0 / 20.0 * r2 + 3.0 / 80.0 * h2;
  return centred(md, pi * r2 * height / 3.0, Eigen::Vector3d(transverse, transverse, 0.3 * r2));
}

SpatialInertia solid_ellipsoid(const Eigen::Vector3d& semi_axes, MassOrDensity md) {
  require_size(semi_axes, "semi_axes");
  const Eigen::Vector3d s2 = semi_axes.cwiseAbs2();
  return centred(md, 4.0 / 3.0 * pi * semi_axes.prod(), Eigen::Vector3d(s2(1) + s2(2), s2(0) + s2(2), s2(0) + s2(1)) / 5.0);
}

SpatialInertia solid_capsule(double radius, double length, MassOrDensity md) {
  require_positive(radius, "radius");
  if (!(std::isfinite(length) && length >= 0.0)) throw_invalid("length", "a finite number >= 0", length);
  const double r = radius, h = length;
  // per unit density: cylinder and one hemisphere
  const double m_c = pi * r * r * h, m_h = 2.0 / 3.0 * pi * r * r * r;
  const double volume = m_c + 2.0 * m_h;
  const double I_zz = m_c * r * r / 2.0 + 0.8 * m_h * r * r;
  const double I_xx = m_c * (h * h / 12.0 + r * r / 4.0) + 2.0 * m_h * (0.4 * r * r + h * h / 4.0 + 0.375 * h * r);
  return centred(md, volume, Eigen::Vector3d(I_xx, I_xx, I_zz) / volume);
}

SpatialInertia solid_tetrahedron(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1, const Eigen::Vector3d& v2,
                                 const Eigen::Vector3d& v3, MassOrDensity md) {
  const Eigen::Vector3d* v[4] = {&v0, &v1, &v2, &v3};
  for (int i = 0; i < 4; ++i) require_finite(*v[i], "v" + std::to_string(i));
  Eigen::Matrix3d edges;
  edges << v1 - v0, v2 - v0, v3 - v0;
  const double volume = std::abs(edges.determinant()) / 6.0;
  const double scale = edges.colwise().norm().prod();
  if (!(volume > 1e-12 * scale)) throw_invalid("vertices", "a tetrahedron of nonzero volume", "volume " + format_value(volume));
  const Eigen::Vector3d com = (v0 + v1 + v2 + v3) / 4.0;
  // about the centroid, s = 0: integral d d^T dV = V/20 sum d_i d_i^T
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 4; ++i) D += (*v[i] - com) * (*v[i] - com).transpose();
  const double m = md.mass_of(volume);
  return SpatialInertia(m, com, inertia_from_second_moment(m / 20.0 * D));
}

}  // namespace rigiddyn
