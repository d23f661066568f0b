// Kinematic trees: the algorithms against their dense definitions on a small tree of every joint kind
// (H = sum J^T I J with link Jacobians from forward kinematics of unit velocities; ABA inverts RNEA;
// CRBA's columns are RNEA differences), the validation messages, and that no algorithm allocates once
// the workspace is built (the heap counted by allocation_count.hpp).
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigiddyn/tree/aba.hpp"
#include "rigiddyn/tree/crba.hpp"
#include "rigiddyn/tree/energy.hpp"
#include "rigiddyn/tree/forward_kinematics.hpp"
#include "rigiddyn/tree/rnea.hpp"
#include "rigiddyn/tree/tree.hpp"
#include "rigiddyn/tree/workspace.hpp"

#include "allocation_count.hpp"

namespace rigiddyn {
namespace {

SpatialInertia box(double mass, const Eigen::Vector3d& com) {
  return SpatialInertia(mass, com, Eigen::Vector3d(0.1, 0.12, 0.15).asDiagonal().toDenseMatrix());
}

Transform placement(double angle, const Eigen::Vector3d& axis, const Eigen::Vector3d& p) {
  return Transform(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), p);
}

// A free base with a branch of every other joint kind.
Tree every_joint_kind() {
  Tree tree(Eigen::Vector3d(0.0, 0.0, -9.81));
  tree.add_link("base", -1, FreeJoint(), box(2.0, Eigen::Vector3d(0.1, 0.0, 0.0)), Transform());
  tree.add_link("shoulder", 0, SphericalJoint(), box(1.0, Eigen::Vector3d(0.2, 0.1, 0.0)),
                placement(0.3, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.3, 0.0, 0.1)));
  tree.add_link("elbow", 1, RevoluteJoint(Eigen::Vector3d(0, 1, 1)), box(0.8, Eigen::Vector3d(0.2, 0.0, -0.1)),
                placement(-0.7, Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0.4, 0.0, 0.0)));
  tree.add_link("slide", 0, PrismaticJoint(Eigen::Vector3d(1, 0, 0)), box(0.5, Eigen::Vector3d(0.0, 0.1, 0.0)),
                placement(1.1, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(-0.2, 0.3, 0.0)));
  tree.add_link("tool", 2, FixedJoint(), box(0.3, Eigen::Vector3d(0.05, 0.0, 0.0)),
                placement(0.5, Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0.3, 0.0, 0.0)));
  return tree;
}

Eigen::VectorXd configuration(const Tree& tree) {
  Eigen::VectorXd q = tree.neutral_configuration();
  const Eigen::Quaterniond q_base(Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -1, 2).normalized()));
  const Eigen::Quaterniond q_ball(Eigen::AngleAxisd(-1.3, Eigen::Vector3d(0, 1, 2).normalized()));
  q.head<3>() << 0.5, -0.2, 1.0;
  q.segment<4>(3) = q_base.coeffs();
  q.segment<4>(7) = q_ball.coeffs();
  q[11] = 0.9;   // elbow
  q[12] = -0.3;  // slide
  return q;
}

Eigen::VectorXd ramp(int n, double start) {
  return Eigen::VectorXd::LinSpaced(n, start, start + 0.37 * n);
}

TEST(Tree, MassMatrixIsTheSumOfJacobianInertias) {
  const Tree tree = every_joint_kind();
  TreeWorkspace ws(tree);
  const Eigen::VectorXd q = configuration(tree);
  const int nv = tree.nv();
  // J_i column k = the twist of link i (in L_i) for the unit velocity e_k (forward kinematics)
  std::vector<Eigen::MatrixXd> J(tree.num_links(), Eigen::MatrixXd(6, nv));
  for (int k = 0; k < nv; ++k) {
    forward_kinematics(tree, q, Eigen::VectorXd::Unit(nv, k), ws);
    for (int i = 0; i < tree.num_links(); ++i) J[i].col(k) = ws.v[i].to_vector();
  }
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nv, nv);
  for (int i = 0; i < tree.num_links(); ++i) H += J[i].transpose() * tree.link(i).I * J[i];
  // sums of products of order-1 terms over 5 links: 1e-13 absolute covers ~100 eps per entry
  EXPECT_LE((crba(tree, q, ws) - H).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Tree, AbaInvertsRneaAndCrbaColumnsAreRneaDifferences) {
  const Tree tree = every_joint_kind();
  TreeWorkspace ws(tree);
  const Eigen::VectorXd q = configuration(tree), v = ramp(tree.nv(), -1.0), a = ramp(tree.nv(), 0.5);
  std::vector<Force> f_ext(tree.num_links(), Force(Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1.0, 0.0, -2.0)));
  const Eigen::VectorXd tau = rnea(tree, q, v, a, f_ext, ws);
  // the error of H^-1 (tau - C) is cond(H) eps |tau| (cond(H) < 1e3 here)
  EXPECT_LE((aba(tree, q, v, tau, f_ext, ws) - a).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::MatrixXd H = crba(tree, q, ws);
  const Eigen::VectorXd C = bias_forces(tree, q, v, ws);
  for (int k = 0; k < tree.nv(); ++k) {
    const Eigen::VectorXd column = rnea(tree, q, v, Eigen::VectorXd::Unit(tree.nv(), k), {}, ws) - C;
    EXPECT_LE((column - H.col(k)).cwiseAbs().maxCoeff(), 1e-12) << "column " << k;
  }
  EXPECT_NEAR(kinetic_energy(tree, q, v, ws), 0.5 * v.dot(H * v), 1e-12 * v.squaredNorm());
}

TEST(Tree, ValidationNamesTheLink) {
  Tree tree;
  tree.add_link("base", -1, RevoluteJoint(), box(1.0, Eigen::Vector3d::Zero()), Transform());
  try {
    tree.add_link("arm", 5, RevoluteJoint(), box(1.0, Eigen::Vector3d::Zero()), Transform());
    FAIL() << "a parent after the link was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("link 1 ('arm'): parent"), std::string::npos) << e.what();
  }
  EXPECT_THROW(tree.add_link("bob", 0, RevoluteJoint(), SpatialInertia::point_mass(1.0, Eigen::Vector3d::UnitX()),
                             Transform()),
               std::invalid_argument);
  EXPECT_THROW(RevoluteJoint(Eigen::Vector3d::Zero()), std::invalid_argument);
}

TEST(Tree, NoAlgorithmAllocatesOnceTheWorkspaceIsBuilt) {
  if (!test::counts_allocations) GTEST_SKIP() << test::why_not_counted;
  const Tree tree = every_joint_kind();
  TreeWorkspace ws(tree);
  const Eigen::VectorXd q = configuration(tree), v = ramp(tree.nv(), -1.0), a = ramp(tree.nv(), 0.5);
  Eigen::VectorXd q_next(tree.nq());
  const std::vector<Force> f_ext(tree.num_links());
  using test::allocations_during;
  EXPECT_EQ(allocations_during([&] { forward_kinematics(tree, q, v, ws); }), 0) << "forward_kinematics";
  EXPECT_EQ(allocations_during([&] { rnea(tree, q, v, a, f_ext, ws); }), 0) << "rnea";
  EXPECT_EQ(allocations_during([&] { bias_forces(tree, q, v, ws); }), 0) << "bias_forces";
  EXPECT_EQ(allocations_during([&] { crba(tree, q, ws); }), 0) << "crba";
  EXPECT_EQ(allocations_during([&] { aba(tree, q, v, ws.zero_v, f_ext, ws); }), 0) << "aba";
  EXPECT_EQ(allocations_during([&] { kinetic_energy(tree, q, v, ws); }), 0) << "kinetic_energy";
  EXPECT_EQ(allocations_during([&] { potential_energy(tree, q, ws); }), 0) << "potential_energy";
  EXPECT_EQ(allocations_during([&] { tree.integrate(q, v, 0.01, q_next); }), 0) << "integrate";
}

}  // namespace
}  // namespace rigiddyn
