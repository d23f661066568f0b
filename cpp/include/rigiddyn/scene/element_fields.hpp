// The field table of a force element spec: each field's key, the member it sets, its SI unit, whether it
// must be given, the bound on its value and its docstring. A spec lists its fields once, in its own file
// (`static constexpr auto fields()`), with its class docstring (`doc`); the Python class (its keyword
// constructor, attributes, repr and pickle), the scene file's [[force]] tables and describe() are all
// generated from that table. The default of a field that need not be given is the spec's member default.
#pragma once
#include "rigiddyn/scene/body.hpp"

#include <Eigen/Core>

#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace rigiddyn {

// How a field's value is read, from its member type: scalar (double), vector (Eigen::Vector3d, shape
// (3,)), array (std::vector<double>, shape (n,), a table's column), bodies (BodyList: none, every body), body
// (int, a body index), loads (a schedule), frame (Frame), callable (a function); optional_body is a body index
// or none (stored as −1).
enum class FieldKind { scalar, vector, array, bodies, body, optional_body, loads, frame, callable };

// The bound a scalar field's value must satisfy (besides being finite).
enum class FieldBound { any, nonnegative, positive };

// One field of Spec, whose value is the member `member` of type T.
template <class Spec, class T>
struct ElementField {
  const char* key;         // the keyword argument, attribute and scene-file key
  T Spec::*member;         // the spec's member it sets
  FieldKind kind;
  const char* unit;        // its SI unit in pint syntax ("" when it has none)
  const char* doc;         // one line: what it is, its frame and shape
  bool required = false;   // it must be given (the member's default is only a placeholder)
  FieldBound bound = FieldBound::any;
  bool infinite_ok = false;  // a scalar that may be ±∞ (a time without end)

  constexpr ElementField must_be_given() const {
    ElementField f = *this;
    f.required = true;
    return f;
  }
  constexpr ElementField at_least_zero() const {
    ElementField f = *this;
    f.bound = FieldBound::nonnegative;
    return f;
  }
  constexpr ElementField above_zero() const {
    ElementField f = *this;
    f.bound = FieldBound::positive;
    return f;
  }
  constexpr ElementField may_be_infinite() const {
    ElementField f = *this;
    f.infinite_ok = true;
    return f;
  }
};

// A scalar [unit], a (3,) vector [unit], an (n,) array [unit] (each entry finite), the bodies it acts on, one
// body, a body or none.
template <class Spec>
constexpr ElementField<Spec, double> scalar_field(const char* key, double Spec::*member, const char* unit, const char* doc) {
  return {key, member, FieldKind::scalar, unit, doc};
}
template <class Spec>
constexpr ElementField<Spec, Eigen::Vector3d> vector_field(const char* key, Eigen::Vector3d Spec::*member, const char* unit,
                                                           const char* doc) {
  return {key, member, FieldKind::vector, unit, doc};
}
template <class Spec>
constexpr ElementField<Spec, std::vector<double>> array_field(const char* key, std::vector<double> Spec::*member,
                                                              const char* unit, const char* doc) {
  return {key, member, FieldKind::array, unit, doc};
}
template <class Spec>
constexpr ElementField<Spec, BodyList> bodies_field(BodyList Spec::*member,
                                                    const char* doc = "None (every body) or a tuple of the indices of "
                                                                      "the bodies it acts on") {
  return {"bodies", member, FieldKind::bodies, "", doc};
}
template <class Spec>
constexpr ElementField<Spec, int> body_field(const char* key, int Spec::*member, const char* doc) {
  return ElementField<Spec, int>{key, member, FieldKind::body, "", doc}.must_be_given();
}
template <class Spec>
constexpr ElementField<Spec, int> optional_body_field(const char* key, int Spec::*member, const char* doc) {
  return {key, member, FieldKind::optional_body, "", doc};
}

// Whether Spec declares check_fields() (what its fields must satisfy together, throwing
// std::invalid_argument "<field>: expected ..."), and whether it declares keyword_only (its Python class takes
// every field by keyword unless it is false).
template <class Spec, class = void>
struct has_field_check : std::false_type {};
template <class Spec>
struct has_field_check<Spec, std::void_t<decltype(std::declval<const Spec&>().check_fields())>> : std::true_type {};
template <class Spec, class = void>
struct has_keyword_only : std::false_type {};
template <class Spec>
struct has_keyword_only<Spec, std::void_t<decltype(Spec::keyword_only)>> : std::true_type {};

// Whether Spec has switch times (`std::vector<AppliedLoad> switches() const`: each t_start and t_end is one),
// at which a run splits its steps and sets its terms' pieces (set_time).
template <class Spec, class = void>
struct has_switches : std::false_type {};
template <class Spec>
struct has_switches<Spec, std::void_t<decltype(std::declval<const Spec&>().switches())>> : std::true_type {};

// Calls f(field) for each field of Spec's table, in order.
template <class Spec, class F>
void for_each_field(F&& f) {
  std::apply([&](const auto&... field) { (f(field), ...); }, Spec::fields());
}

// The number of fields of Spec.
template <class Spec>
constexpr std::size_t field_count() {
  return std::tuple_size_v<decltype(Spec::fields())>;
}

}  // namespace rigiddyn
