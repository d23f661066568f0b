// Dense 6x6 spatial cross-product operators (Featherstone, angular first), used as test oracles and
// where a matrix is needed; the structured forms are Motion::cross.
//   crm(m) = [[w^, 0], [v^, w^]]  so crm(m) m2 = m x m2
//   crf(m) = [[w^, v^], [0, w^]] = -crm(m)^T  so crf(m) f = m x* f
#pragma once
#include "rigiddyn/spatial/motion.hpp"

namespace rigiddyn {

Matrix6d motion_cross_matrix(const Motion& m);
Matrix6d force_cross_matrix(const Motion& m);

}  // namespace rigiddyn
