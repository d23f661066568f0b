// Tags naming the flow of the free part (no load) that a model's free_flow<Rotation>(y, h) applies to
// each body (model_interface.hpp): every body's position moves by h v, and an attitude by
//   DlmRotation<normalise>  the DLM splitting of the Euler–Poinsot flow (Dullweber, Leimkuhler &
//                           McLachlan 1997; splitting_dlm.hpp: dlm_free_rotation), the quaternion
//                           normalised at the end unless `normalise` is false (Yoshida4 normalises once
//                           per step);
//   ExactRotation           the exact Euler–Poinsot flow in closed form (exact/free_body.hpp;
//                           exact_flow_kick.hpp: exact_free_rotation).
// A model without attitudes (particle) ignores the tag; a body turning about a fixed axis (planar body)
// has no gyroscopic term, so its free rotation θ += h ω is the same exact flow under both.
#pragma once

namespace rigiddyn {

template <bool normalise>
struct DlmRotation {};

struct ExactRotation {};

}  // namespace rigiddyn
