#include "rigiddyn/simulate/global_error.hpp"

#include "numbers.hpp"
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/angular_distance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <charconv>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numeric>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>

namespace rigiddyn {

namespace {

using detail::nan;


// The round-off a run of `steps` steps can accumulate in a quantity of size `size`: a relative
// 8 ε_machine per step, summed (a bound: rounding errors add up at most linearly).
double round_off_bound(double size, std::int64_t steps) {
  return 8.0 * DBL_EPSILON * std::abs(size) * static_cast<double>(std::max<std::int64_t>(steps, 1));
}

// Body b's attitude at record i as recorded (its norm not forced: angular_distance's angle 2 atan2(|d_xyz|, |d_w|) of
// d = q_a^* ⊗ q_b is that of the unit quaternions, d scaling with |q_a| |q_b|, so that no record is normalised)
Eigen::Quaterniond attitude(const ErrorRecords& r, std::size_t i, std::int64_t b) {
  const double* q = r.q_WB + (i * r.bodies + b) * 4;
  if (r.scalar_first) return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  return Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
}

Eigen::Map<const Eigen::Vector3d> vector3(const double* rows, const ErrorRecords& r, std::size_t i, std::int64_t b) {
  return Eigen::Map<const Eigen::Vector3d>(rows + (i * r.bodies + b) * 3);
}

// |T| + |V| at record i: the size the round-off of the total energy T + V scales with [J].
double energy_size_of(const ErrorRecords& r, std::size_t i) {
  return std::abs(r.energy_scale[i]) + std::abs(r.energy[i] - r.energy_scale[i]);
}

// A verdict's text built in place, printf's "%.<precision>g" by std::to_chars (the same text, C++17 [charconv]): a
// verdict is formatted at every common record whose order check fails, where snprintf cost ~2 500 instructions a
// record (4x std::to_chars)
class Text {
 public:
  struct General {
    double x;
    int precision;
  };
  static General general(double x, int precision) { return {x, precision}; }

  Text& operator<<(std::string_view s) {
    const std::size_t n = std::min(s.size(), static_cast<std::size_t>(end() - tail_));
    tail_ = std::copy_n(s.data(), n, tail_);
    return *this;
  }
  Text& operator<<(const char* s) { return *this << std::string_view(s); }
  Text& operator<<(int k) {
    tail_ = std::to_chars(tail_, end(), k).ptr;
    return *this;
  }
  Text& operator<<(General g) {
    tail_ = std::to_chars(tail_, end(), g.x, std::chars_format::general, g.precision).ptr;
    return *this;
  }
  std::string_view view() const { return {text_, static_cast<std::size_t>(tail_ - text_)}; }

 private:
  char* end() { return text_ + sizeof text_; }
  char text_[192];
  char* tail_ = text_;
};

// A code that two numbers share only if printf's "%.2g" prints them alike, found without printing them: the sign,
// the decade e of |x| (10^e <= |x| < 10^(e+1), |e| <= 20) and k = round(|x| 10^(1 − e)) in [10, 100], |x| rounded
// to two significant digits, from which "%.2g" prints (ISO C 7.21.6.1: %g rounds to the precision's significant
// digits, then chooses its style from that rounded value's exponent); ±0 a code of its own. −1 for NaN, outside those
// decades, and where |x| 10^(1 − e) lies within 10⁻⁶ of a tie between two k (its one rounding, ≤ 2⁻⁴⁶ there, could
// then have moved it across the tie that printf rounds exactly). The decade from log10, moved by one where its
// rounding put |x| 10^(1 − e) outside [10, 100) (10^n is exact in double for 0 <= n <= 22: |x| 10^n or |x| / 10^(−n)
// is one rounding).
int two_digit_code(double x) {
  const int sign = std::signbit(x) ? 1 : 0;
  const double size = std::abs(x);
  if (size == 0.0) return sign;
  if (!(size >= 1e-20 && size < 1e20)) return -1;  // NaN too
  int e = static_cast<int>(std::floor(std::log10(size)));
  double scaled = 0.0;
  for (int tries = 0; tries < 3; ++tries) {
    const int n = 1 - e;
    scaled = n >= 0 ? size * std::pow(10.0, n) : size / std::pow(10.0, -n);
    if (scaled >= 10.0 && scaled < 100.0) break;
    e += scaled < 10.0 ? -1 : 1;
  }
  if (!(scaled >= 10.0 && scaled < 100.0)) return -1;
  const double k = std::round(scaled);
  if (std::abs(scaled - k) > 0.5 - 1e-6) return -1;
  return ((e + 32) * 128 + static_cast<int>(k)) * 2 + sign;  // >= 2 · 12 · 128: apart from ±0's
}

// The verdicts "not asymptotic: observed order <%.2g> where <p> is expected (<quantity>)" of one estimate's common
// records, each text made once: where the order check fails at most common records (a run recording every step
// whose error falls faster than dt^p), printing the order (std::to_chars, ~670 instructions) and finding its
// text (~580) at each cost more than the record's comparisons. Two orders with the same two_digit_code print alike,
// so that their records share a text found by the code.
class NotAsymptoticTexts {
 public:
  explicit NotAsymptoticTexts(int order) : order_(order) {}

  // The index in `verdicts`' texts of the verdict for the observed order `observed` of `quantity` (a string literal,
  // told apart by its address).
  std::uint32_t index(double observed, const char* quantity, Verdicts& verdicts) {
    const int code = two_digit_code(observed);
    const std::uint64_t key = (static_cast<std::uint64_t>(slot(quantity)) << 32) | static_cast<std::uint32_t>(code);
    if (code >= 0) {
      const auto found = known_.find(key);
      if (found != known_.end()) return found->second;
    }
    Text text;
    text << "not asymptotic: observed order " << Text::general(observed, 2) << " where " << order_ << " is expected ("
         << quantity << ")";
    const std::uint32_t k = verdicts.add_text(text.view());
    if (code >= 0) known_.emplace(key, k);
    return k;
  }

 private:
  // the position of `quantity` among those seen (six at most: the kinds of quantity an estimate checks)
  std::uint32_t slot(const char* quantity) {
    const auto found = std::find(quantities_.begin(), quantities_.end(), quantity);
    if (found != quantities_.end()) return static_cast<std::uint32_t>(found - quantities_.begin());
    quantities_.push_back(quantity);
    return static_cast<std::uint32_t>(quantities_.size() - 1);
  }

  int order_;
  std::vector<const char*> quantities_;
  std::unordered_map<std::uint64_t, std::uint32_t> known_;  // (quantity's slot, code) → text index
};

// The differences of one quantity at a common record: d1 = d(y_h, y_2h), d2 = d(y_2h, y_4h) and the round-off
// bound of y_h.
struct Differences {
  double d1, d2, round_off;
};

// The differences of the bodies' values of one kind of quantity taken together: d1 and d2 the norms of the bodies'
// differences, the round-off bound their sum. Checking the order on these rather than body by body keeps a body
// whose own error crosses zero at the record (where its ratio r says nothing) from failing the check alone.
// One body's differences are their own total: no squares summed and no square root of them, which the single body of
// most runs would pay for at every record.
struct CombinedDifferences {
  double d1_squared = 0.0, d2_squared = 0.0, round_off = 0.0;
  Differences first{};
  int count = 0;

  void add(const Differences& d) {
    if (count++ == 0) {
      first = d;
    } else {
      if (count == 2) sum(first);  // a second body: the first's squares join the sums
      sum(d);
    }
  }
  Differences total() const {
    return count == 1 ? first : Differences{std::sqrt(d1_squared), std::sqrt(d2_squared), round_off};
  }

 private:
  void sum(const Differences& d) { d1_squared += d.d1 * d.d1, d2_squared += d.d2 * d.d2, round_off += d.round_off; }
};

// What one common record's quantities say: the estimate of each, and the record's observed order and verdict
// (those of the quantity whose ratio r is furthest from 2^p, unless a run diverged).
class CommonRecord {
 public:
  // expected = 2^p; coarse_problem: why the record is not reliable whatever its differences say (null: none)
  CommonRecord(double expected, const char* coarse_problem) : expected_(expected) {
    if (coarse_problem != nullptr) blocked_ = coarse_problem;
  }

  // ε of one body's value of a quantity (its order checked with the other bodies', by check()).
  double estimate(const Differences& d) {
    if (d.d1 <= d.round_off) return d.round_off;  // at round-off level: its bound
    if (!std::isfinite(d.d1)) {
      block("step beyond the stability limit: the run at h or 2h diverged");
      return nan;
    }
    return d.d1 / (expected_ - 1.0);  // leading error term of y_h
  }

  // The observed order of a kind of quantity `quantity` named `name` (the differences of its bodies together): r must
  // lie in [2^p / 1.5, 2^p · 1.5].
  void check(const Differences& d, ErrorMeasure quantity, const char* name) {
    estimated_ |= measure_bit(quantity);
    ratio(d, quantity, name, expected_);
  }

  // ε of a conserved quantity of the run (energy, |L|), whose error may fall faster than h^p: the leading term
  // of an invariant's error often vanishes (rk4 conserves a quadratic invariant of a linear problem to
  // O(h^(p+1))). Its r may lie in [2^p / 1.5, 2^(p+1) · 1.5]; above 2^p · 1.5 the estimate takes the observed
  // order q = log2 r: ε = d1 / (2^q − 1) = d1 / (r − 1), the leading term of an error C h^q.
  double invariant(const Differences& d, ErrorMeasure quantity, const char* name) {
    estimated_ |= measure_bit(quantity);
    const double epsilon = estimate(d);
    if (!(d.d1 > d.round_off) || !std::isfinite(d.d1)) return epsilon;
    const double r = ratio(d, quantity, name, 2.0 * expected_);
    return r > expected_ * record_window && r <= 2.0 * expected_ * record_window ? d.d1 / (r - 1.0) : epsilon;
  }

  // The record is not reliable, for the reason `why` (the first given is kept).
  void block(const std::string& why) {
    if (blocked_.empty()) blocked_ = why;
  }

  double observed_order() const { return std::log2(worst_r_); }
  // The quantities whose estimate is reliable at this record (GlobalErrorEstimate's reliable_quantities): none where
  // the record is blocked; every one checked where the record is reliable; else those inside quantity_window.
  std::uint8_t reliable_quantities() const {
    if (!blocked_.empty()) return 0;
    return static_cast<std::uint8_t>(outside_ == 0 ? estimated_ : estimated_ & ~outside_alone_);
  }
  double expected_ratio() const { return expected_; }
  // Record j of `verdicts` becomes this record's verdict, its observed order `observed` (observed_order()) where the
  // check failed (a record compares several quantities before it knows its worst).
  // `reliable`: the index of reliable_verdict in `verdicts`' texts.
  void put_verdict(Verdicts& verdicts, NotAsymptoticTexts& texts, std::uint32_t reliable, std::size_t j,
                   double observed) const {
    if (!blocked_.empty()) return verdicts.set(j, blocked_);
    if (!worst_outside_) return verdicts.set_text(j, reliable);
    verdicts.set_text(j, texts.index(observed, worst_name_, verdicts));
  }

 private:
  // r = d2 / d1 checked against [2^p / record_window, top · record_window] (top = 2^p, or 2^(p+1) for an invariant);
  // the quantity furthest from 2^p names the record's order and, outside the window, its verdict; and against
  // quantity_window's, for the quantity alone. Returns r (NaN where not measured).
  double ratio(const Differences& d, ErrorMeasure quantity, const char* name, double top) {
    if (d.d1 <= d.round_off) return nan;  // at round-off level: no order to check
    if (!std::isfinite(d.d1)) {
      block("step beyond the stability limit: the run at h or 2h diverged");
      return nan;
    }
    if (!std::isfinite(d.d2)) {
      block("step beyond the stability limit: the run at 4h diverged");
      return nan;
    }
    const double expected = expected_;
    const double r = d.d2 / d.d1;
    const bool inside = r >= expected / record_window && r <= top * record_window;
    if (!inside) outside_ |= measure_bit(quantity);
    if (!(r >= expected / quantity_window && r <= top * quantity_window)) outside_alone_ |= measure_bit(quantity);
    const double distance = std::max(r / expected, expected / r);  // orders as |log(r / 2^p)| does
    // a quantity outside its window names the record before any inside it, then the furthest from 2^p
    if (std::make_pair(!inside, distance) > std::make_pair(worst_outside_, worst_distance_)) {
      worst_outside_ = !inside, worst_distance_ = distance, worst_r_ = r, worst_name_ = name;
    }
    return r;
  }

  double expected_;  // 2^p, the ratio r of the asymptotic regime
  std::string blocked_;
  bool worst_outside_ = false;
  double worst_distance_ = -1.0;
  double worst_r_ = nan;           // r of the quantity furthest from 2^p (its observed order log2 r)
  const char* worst_name_ = "";    // and its name (a string literal: check's and invariant's names are)
  // the quantities checked, those outside record_window's window and those outside quantity_window's (measure_bit)
  std::uint8_t estimated_ = 0, outside_ = 0, outside_alone_ = 0;
};

// The estimates of the common records, a row each in the layout of GlobalErrorEstimate: sized once (a row's
// per-body quantities are a slice of one array, not a vector of their own: an estimate allocates per run, not per
// record).
struct CommonTable {
  std::size_t nb;
  std::vector<double> attitude, angular_velocity, position, velocity;  // (rows, nb)
  std::vector<double> energy, angular_momentum, observed_order;        // (rows,)
  std::vector<std::uint8_t> reliable_quantities;                       // (rows,)
  Verdicts verdict;                                                    // (rows,)
  NotAsymptoticTexts not_asymptotic;                                   // verdict's texts of failed order checks
  std::uint32_t reliable_text;                                         // reliable_verdict's index in verdict

  // for an estimate of a method of order `order`
  CommonTable(std::size_t rows, std::size_t bodies, int order)
      : nb(bodies), attitude(rows * bodies, nan), angular_velocity(rows * bodies, nan), position(rows * bodies, nan),
        velocity(rows * bodies, nan), energy(rows, nan), angular_momentum(rows, nan), observed_order(rows, nan),
        reliable_quantities(rows, 0), not_asymptotic(order) {
    verdict.assign(rows, reliable_verdict);
    reliable_text = verdict.add_text(reliable_verdict);
  }
  std::size_t rows() const { return energy.size(); }
  // the four per-body arrays, in the order of GlobalErrorEstimate's
  std::array<std::vector<double>*, 4> states() { return {&attitude, &angular_velocity, &position, &velocity}; }
  std::array<const std::vector<double>*, 4> states() const {
    return {&attitude, &angular_velocity, &position, &velocity};
  }
};

// The differences at common record j (answer record i, coarse records j): the coarse values are read where the
// coarse run has them (a diverged coarse run has fewer records: its differences are then +inf).
template <class Distance>
Differences differences(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4, std::size_t i,
                        std::size_t j, double size, std::int64_t steps, Distance distance) {
  const double inf = std::numeric_limits<double>::infinity();
  const double d1 = j < h2.n ? distance(h, i, h2, j) : inf;
  const double d2 = j < h2.n && j < h4.n ? distance(h2, j, h4, j) : inf;
  return {std::isnan(d1) ? inf : d1, std::isnan(d2) ? inf : d2, round_off_bound(size, steps)};
}

// The energy balance B = T − W, whose exact value is B(t0) at every t: its true error |B_h(t) − B_h(t0)| is known.
// A Richardson estimate of it below half that (beyond the round-off) is shown wrong, and with it the estimates of
// the run: its error is not in the leading term that the three runs see alike (e.g. a method that damps a
// nutation at every step size tried, so that the runs agree with each other and not with the motion). Returns the
// reason a record is then not reliable ("" where the balance holds), for a method whose ratio r is 2^p
// (expected_ratio).
std::string balance_problem(double expected_ratio, const ErrorRecords& h, const ErrorRecords& h2,
                            const ErrorRecords& h4, std::size_t i, std::size_t j, double size, std::int64_t steps) {
  const auto balance = [](const ErrorRecords& x, std::size_t a, const ErrorRecords& y, std::size_t c) {
    return std::abs(x.balance[a] - y.balance[c]);
  };
  if (h2.balance.empty() || h4.balance.empty()) return {};
  const Differences d = differences(h, h2, h4, i, j, size, steps, balance);
  const double estimate = d.d1 / (expected_ratio - 1.0);
  const double error = std::abs(h.balance[i] - h.balance[0]);
  if (std::isfinite(d.d1) && error > 2.0 * estimate + 2.0 * d.round_off) {
    Text text;
    text << "not asymptotic: the energy balance T - W is off by " << Text::general(error, 2)
         << " J where its estimate is " << Text::general(estimate, 2) << " J";
    return std::string(text.view());
  }
  return {};
}

// Whether an estimate restricted to `only` (none: every quantity) estimates `quantity`.
bool estimates(std::optional<ErrorMeasure> only, ErrorMeasure quantity) { return !only || *only == quantity; }

// The rows of one measure's estimate alone (its `only`), made beside those of every quantity from the same
// differences (estimate_global_error_and_alone): its table and its measure.
struct Alone {
  CommonTable* table;
  ErrorMeasure measure;
};

// The values of `measure` in a table of an estimate's quantities (a GlobalErrorEstimate, or the CommonTable of its
// common records: the same fields), const or not: (rows, nb) for the state quantities, (rows,) for the energy and |L|
template <class Table>
auto& measure_values(Table& table, ErrorMeasure measure) {
  switch (measure) {
    case ErrorMeasure::attitude: return table.attitude;
    case ErrorMeasure::angular_velocity: return table.angular_velocity;
    case ErrorMeasure::position: return table.position;
    case ErrorMeasure::velocity: return table.velocity;
    case ErrorMeasure::energy: return table.energy;
    case ErrorMeasure::angular_momentum: return table.angular_momentum;
  }
  throw_invalid("measure", "a rigiddyn::ErrorMeasure", static_cast<int>(measure));
}

// Row j of `out`: the estimates of common record j (answer record i), for a method of order p (expected_ratio = 2^p),
// of the quantities `only` allows (estimate_global_error); with_alone: also row j of alone.table, the estimate of
// alone.measure alone (`only` none), from the same differences, as estimate_common with `only` = alone.measure makes
// it (its record's checks those of that measure and the energy balance's).
// (inlined into its callers: out of line, its arguments passed at every record cost 6 % of a free body's estimate)
template <bool with_alone>
RIGIDDYN_ALWAYS_INLINE void estimate_common(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                                            std::size_t i, std::size_t j, std::int64_t steps, double expected_ratio,
                                            const char* coarse_problem, std::optional<ErrorMeasure> only,
                                            CommonTable& out, Alone alone) {
  CommonRecord record(expected_ratio, coarse_problem);
  CommonRecord alone_record(expected_ratio, coarse_problem);  // (with_alone only)
  const auto is_alone = [&](ErrorMeasure quantity) {
    if constexpr (with_alone) {
      return quantity == alone.measure;
    } else {
      return false;
    }
  };
  const std::int64_t nb = h.bodies;
  // the differences of a kind of quantity, body by body: their estimates, then their order checked together
  const auto kind = [&](std::vector<double>& values, ErrorMeasure quantity, const char* name, auto distance_of_body,
                        auto size_of_body) {
    CombinedDifferences bodies;
    double* row = values.data() + j * out.nb;
    double* alone_row = is_alone(quantity) ? measure_values(*alone.table, quantity).data() + j * out.nb : nullptr;
    for (std::int64_t b = 0; b < nb; ++b) {
      const Differences d = differences(h, h2, h4, i, j, size_of_body(b), steps, distance_of_body(b));
      bodies.add(d);
      row[b] = record.estimate(d);
      if (alone_row != nullptr) alone_row[b] = alone_record.estimate(d);
    }
    record.check(bodies.total(), quantity, name);
    if (alone_row != nullptr) alone_record.check(bodies.total(), quantity, name);
  };
  if (estimates(only, ErrorMeasure::attitude)) {
    kind(out.attitude, ErrorMeasure::attitude, "attitude",
         [](std::int64_t b) {
           return [b](const ErrorRecords& x, std::size_t a, const ErrorRecords& y, std::size_t c) {
             return angular_distance(attitude(y, c, b), attitude(x, a, b));
           };
         },
         [](std::int64_t) { return 1.0; });
  }
  const auto vector_kind = [&](ErrorMeasure quantity, std::vector<double>& values, const double* ErrorRecords::*rows,
                               const char* name) {
    if (!estimates(only, quantity)) return;
    kind(values, quantity, name,
         [rows](std::int64_t b) {
           return [rows, b](const ErrorRecords& x, std::size_t a, const ErrorRecords& y, std::size_t c) {
             return (vector3(x.*rows, x, a, b) - vector3(y.*rows, y, c, b)).norm();
           };
         },
         [&, rows](std::int64_t b) { return vector3(h.*rows, h, i, b).norm(); });
  };
  vector_kind(ErrorMeasure::angular_velocity, out.angular_velocity, &ErrorRecords::w_B, "angular velocity");
  vector_kind(ErrorMeasure::position, out.position, &ErrorRecords::p_W, "position");
  vector_kind(ErrorMeasure::velocity, out.velocity, &ErrorRecords::v_W, "velocity");
  const auto scalar = [](const double* ErrorRecords::*column) {
    return [column](const ErrorRecords& x, std::size_t a, const ErrorRecords& y, std::size_t c) {
      return std::abs((x.*column)[a] - (y.*column)[c]);
    };
  };
  const bool with_energy = estimates(only, ErrorMeasure::energy);
  const bool with_balance = !h.balance.empty();
  const double energy_size = with_energy || with_balance ? energy_size_of(h, i) : 0.0;
  if (with_energy) {
    const Differences energy = differences(h, h2, h4, i, j, energy_size, steps, scalar(&ErrorRecords::energy));
    // a run whose step is beyond the stability limit gains energy exponentially: the run at 4h (the first to go)
    // then differs from the one at 2h by more than the whole energy |T| + |V| (a chaotic motion keeps its energy)
    if (std::isfinite(energy.d2) && energy.d2 > energy_size && energy_size > 0.0) {
      const char* why = "step beyond the stability limit: the energy of the run at 4h departs from the run at 2h's by "
                        "more than |T| + |V|";
      record.block(why);
      if (is_alone(ErrorMeasure::energy)) alone_record.block(why);
    }
    out.energy[j] = record.invariant(energy, ErrorMeasure::energy, "energy");
    if (is_alone(ErrorMeasure::energy)) {
      alone.table->energy[j] = alone_record.invariant(energy, ErrorMeasure::energy, "energy");
    }
  }
  // the balance B = T − W rounds off at the size of its terms, not of B (released at rest, B = T(t0) = 0): |T| + |V|
  // and the work |W| = |T − B| done so far
  if (with_balance) {
    const double balance_size = energy_size + std::abs(h.energy_scale[i] - h.balance[i]);
    const std::string why = balance_problem(expected_ratio, h, h2, h4, i, j, balance_size, steps);
    if (!why.empty()) {
      record.block(why);
      if constexpr (with_alone) alone_record.block(why);
    }
  }
  if (estimates(only, ErrorMeasure::angular_momentum)) {
    const auto momentum = [](const ErrorRecords& x, std::size_t a, const ErrorRecords& y, std::size_t c) {
      return std::abs(x.momentum[a] - y.momentum[c]);
    };
    const double momentum_size = h.momentum_scale.empty() ? h.momentum[i] : h.momentum_scale[i];
    const Differences d = differences(h, h2, h4, i, j, momentum_size, steps, momentum);
    out.angular_momentum[j] = record.invariant(d, ErrorMeasure::angular_momentum, "angular momentum");
    if (is_alone(ErrorMeasure::angular_momentum)) {
      alone.table->angular_momentum[j] = alone_record.invariant(d, ErrorMeasure::angular_momentum, "angular momentum");
    }
  }
  const auto put = [j](const CommonRecord& r, CommonTable& table) {
    table.observed_order[j] = r.observed_order();
    table.reliable_quantities[j] = r.reliable_quantities();
    r.put_verdict(table.verdict, table.not_asymptotic, table.reliable_text, j, table.observed_order[j]);
  };
  put(record, out);
  if constexpr (with_alone) put(alone_record, *alone.table);
}

// "0.25 s" (3 significant digits).
std::string seconds(double t) {
  Text text;
  text << Text::general(t, 3) << " s";
  return std::string(text.view());
}

// The per-body arrays of an estimate, in the order of CommonTable::states().
std::array<std::vector<double>*, 4> per_body_arrays(GlobalErrorEstimate& e) {
  return {&e.attitude, &e.angular_velocity, &e.position, &e.velocity};
}

// The verdicts of the common records as indices into out.verdict's texts, and whether each text is reliable: a
// record's verdict is then an index copied, not a text compared. out.verdict takes the common records' texts with
// their indices (no text copied or looked up again) and none of their records.
struct CommonVerdicts {
  std::vector<std::uint32_t> text;  // per common record
  std::vector<char> reliable;       // per text

  CommonVerdicts(Verdicts&& common, Verdicts& out) {
    for (const std::string& v : common.texts()) reliable.push_back(is_reliable(v));
    for (std::size_t j = 0; j < common.size(); ++j) text.push_back(common.text_index(j));
    out = std::move(common);
    out.clear_records();
  }
  // The verdict of a record made from common records a and b (a == b: from a alone): the first of theirs that is
  // not reliable, else `how`.
  std::uint32_t first_unreliable_or(std::size_t a, std::size_t b, std::uint32_t how) const {
    return !reliable[text[a]] ? text[a] : (!reliable[text[b]] ? text[b] : how);
  }
};

// Where an answer record's estimate comes from (estimate_global_error): common row a itself; rows a and b blended,
// a·u + b·w with u = 1 − w; row a scaled by w, the blend of a zero estimate and a (0·u + a·w); or none (NaN). Only a
// common row has an observed order.
struct RowSource {
  enum Kind : std::uint8_t { common, blend, scaled, none };
  Kind kind = none;
  std::size_t a = 0, b = 0;
  double u = 1.0, w = 0.0;
};

// One quantity's rows: `width` values a row (a std::size_t, or std::integral_constant 1 for a quantity of the run,
// whose loops the compiler then drops), from the common rows at `from` into the answer rows at `into`.
template <class Width>
struct RowColumn {
  const double* from;
  double* into;
  Width width;

  // answer row i from the common rows as `s` says
  RIGIDDYN_ALWAYS_INLINE void put(const RowSource& s, std::size_t i) const {
    const double *row_a = from + s.a * width, *row_b = from + s.b * width;
    double* row = into + i * width;
    switch (s.kind) {
      case RowSource::common:
        for (std::size_t k = 0; k < width; ++k) row[k] = row_a[k];
        break;
      case RowSource::blend:
        for (std::size_t k = 0; k < width; ++k) row[k] = row_a[k] * s.u + row_b[k] * s.w;
        break;
      case RowSource::scaled:
        for (std::size_t k = 0; k < width; ++k) row[k] = 0.0 * s.u + row_a[k] * s.w;
        break;
      case RowSource::none: break;
    }
  }
};

// Every row of `out`, sized by size_for_records, from the common rows `common` (their sources, `sources`), record by
// record: each source read once for the six quantities (the per-body ones `width` values a row).
template <class Width>
void put_rows(GlobalErrorEstimate& out, const CommonTable& common, const std::vector<RowSource>& sources, Width width) {
  const auto states = common.states();
  const auto into = per_body_arrays(out);
  std::array<RowColumn<Width>, 4> per_body;
  for (std::size_t q = 0; q < states.size(); ++q) per_body[q] = {states[q]->data(), into[q]->data(), width};
  const std::integral_constant<std::size_t, 1> one;
  const RowColumn<decltype(one)> energy{common.energy.data(), out.energy.data(), one},
      momentum{common.angular_momentum.data(), out.angular_momentum.data(), one};
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const RowSource& s = sources[i];
    for (const auto& column : per_body) column.put(s, i);
    energy.put(s, i), momentum.put(s, i);
    if (s.kind == RowSource::common) out.observed_order[i] = common.observed_order[s.a];
  }
}

void put_rows(GlobalErrorEstimate& out, const CommonTable& common, const std::vector<RowSource>& sources) {
  if (common.nb == 1) return put_rows(out, common, sources, std::integral_constant<std::size_t, 1>());
  put_rows(out, common, sources, common.nb);
}

// The rows of `out` where every record is a common record (record_every a multiple of 4): the common rows themselves.
void take_rows(GlobalErrorEstimate& out, CommonTable&& common) {
  const auto states = common.states();
  const auto into = per_body_arrays(out);
  for (std::size_t q = 0; q < states.size(); ++q) *into[q] = std::move(*states[q]);
  out.energy = std::move(common.energy), out.angular_momentum = std::move(common.angular_momentum);
  out.observed_order = std::move(common.observed_order);
}

// Room for n records of nb bodies, their values NaN (a record without an estimate keeps them).
void size_for_records(GlobalErrorEstimate& out, std::size_t n, std::int64_t nb) {
  for (auto* v : per_body_arrays(out)) v->assign(n * nb, nan);
  for (auto* v : {&out.energy, &out.angular_momentum, &out.observed_order}) v->assign(n, nan);
  out.verdict.reserve(n);
}

// The step index of the answer's record i (records every k-th step, and the last).
std::int64_t step_of(std::size_t i, const SimulationOptions& o) {
  return std::min(static_cast<std::int64_t>(i) * o.record_every, o.steps);
}

// The largest estimate of the state quantities (attitude, angular velocity, position, velocity: each over the
// bodies) of row j, kind by kind.
std::array<double, 4> state_sizes(const CommonTable& common, std::size_t j) {
  const auto states = common.states();
  std::array<double, 4> out{};
  for (std::size_t q = 0; q < 4; ++q) {
    const auto row = states[q]->begin() + j * common.nb;
    out[q] = *std::max_element(row, row + common.nb);
  }
  return out;
}

// Past the Lyapunov time: a state estimate whose envelope (its largest value so far) grew more than 1000 (t_j / t_k)^4
// from an earlier common record k (t_k > 0) to record j grew faster than any global error of a regular motion does
// (linearly, or as t² with a drifting frequency): nearby trajectories diverge exponentially, e^{λ t}, and the
// differences soon leave the linear regime that Richardson extrapolation assumes. Every record from there on whose
// order check failed says so, with λ = ln(growth) / (t_j − t_k). The envelope, not each record's estimate: a regular
// motion's error crosses zero again and again (a pendulum's angle error at every swing), and a growth from such a
// record measured 1000 (t_j / t_k)^4 and more on the shipped pendulum. A record's new verdict is made once per text
// (its records share it).
void name_exponential_growth(CommonTable& common, const double* t, const CommonRecords& grid) {
  const auto not_asymptotic = [](const std::string& v) { return v.rfind("not asymptotic", 0) == 0; };
  const std::vector<std::string>& texts = common.verdict.texts();
  if (std::none_of(texts.begin(), texts.end(), not_asymptotic)) return;  // no record a growth would rename
  constexpr double beyond_polynomial = 1000.0;
  std::array<double, 4> envelope{};  // per kind: the largest estimate so far
  std::array<double, 4> least{};     // and the smallest envelope / t^4 of the records before, and its time
  std::array<double, 4> least_t{};
  least.fill(std::numeric_limits<double>::infinity());
  std::string past;
  constexpr std::uint32_t unmade = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renamed(texts.size(), unmade);  // per text of the common records: its renamed text
  for (std::size_t j = 1; j < common.rows(); ++j) {
    if (past.empty()) {  // once named, the growth is not measured again
      const double tj = t[grid.answer_record(j)];
      const std::array<double, 4> sizes = state_sizes(common, j);
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        if (sizes[k] > envelope[k]) envelope[k] = sizes[k];  // (NaN: not estimated, not taken)
      }
      if (!(tj > 0.0)) continue;
      const double t4 = tj * tj * tj * tj;
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        const double scaled = envelope[k] / t4;
        if (std::isfinite(scaled) && scaled > beyond_polynomial * least[k]) {
          const double rate = std::log(scaled / least[k] * std::pow(tj / least_t[k], 4.0)) / (tj - least_t[k]);
          Text text;
          text << "past the Lyapunov time of this scene: the differences grow as e^(" << Text::general(rate, 2)
               << " t) from t = " << Text::general(least_t[k], 3)
               << " s (nearby trajectories diverge exponentially); ";
          past = text.view();
          break;  // named: the smallest estimates are not needed again
        }
        if (scaled > 0.0 && scaled < least[k]) least[k] = scaled, least_t[k] = tj;
      }
    }
    if (past.empty()) continue;
    const std::uint32_t k = common.verdict.text_index(j);  // a text of the common records (renamed ones come after)
    if (renamed[k] == unmade) renamed[k] = not_asymptotic(texts[k]) ? common.verdict.add_text(past + texts[k]) : k;
    common.verdict.set_text(j, renamed[k]);
  }
}

}  // namespace

const std::vector<double>& values_of(const GlobalErrorEstimate& e, ErrorMeasure measure) {
  return measure_values(e, measure);
}

ErrorRecords error_records(const Trajectory& r) {
  ErrorRecords out;
  out.n = r.size();
  out.t = r.t.data(), out.q_WB = r.q_WB.data(), out.w_B = r.w_B.data(), out.p_W = r.p_W.data(), out.v_W = r.v_W.data();
  out.energy = r.total_energy.data(), out.energy_scale = r.kinetic_energy.data();
  out.momentum = r.angular_momentum_norm;
  if (r.work.size() == out.n) {  // T − T(t0) = work (the work of loads and gravity)
    for (std::size_t i = 0; i < out.n; ++i) out.balance.push_back(r.kinetic_energy[i] - r.work[i]);
  }
  return out;
}

SceneColumns scene_columns(const SceneSimulation& r) {
  SceneColumns c;
  c.n = r.size();
  c.bodies = r.body_count;
  c.t = r.t.data(), c.q_WB = r.q_WB.data(), c.w_B = r.w_B.data(), c.p_W = r.p_W.data(), c.v_W = r.v_W.data();
  c.total_energy = r.total_energy.data(), c.angular_momentum_W = r.angular_momentum_W.data();
  c.kinetic_energy = r.kinetic_energy.data(), c.kinetic_energy_size = r.kinetic_energy.size();
  c.mass = r.mass.data(), c.mass_size = r.mass.size();
  c.angular_momentum_O_W = r.angular_momentum_O_W.data(), c.angular_momentum_O_W_size = r.angular_momentum_O_W.size();
  c.work = r.work.data(), c.work_size = r.work.size();
  c.mass_flow_energy = r.mass_flow_energy.data(), c.mass_flow_energy_size = r.mass_flow_energy.size();
  c.motor_work = r.motor_work.data(), c.motor_work_size = r.motor_work.size();
  return c;
}

ErrorRecords error_records(const SceneColumns& r, bool scaled, std::size_t every, std::size_t also) {
  ErrorRecords out;
  out.n = r.n;
  out.bodies = r.bodies;
  out.t = r.t, out.q_WB = r.q_WB, out.w_B = r.w_B, out.p_W = r.p_W, out.v_W = r.v_W;
  out.scalar_first = r.scalar_first;
  out.energy = r.total_energy, out.energy_scale = r.kinetic_energy;
  const std::size_t rows = out.n * static_cast<std::size_t>(out.bodies);
  scaled = scaled && r.mass_size == rows && r.angular_momentum_O_W_size == 3 * rows;  // else |L| itself
  every = std::max<std::size_t>(every, 1);
  // the records every `every`-th, then `also` where it lies between them
  const auto for_each_made = [&](auto&& f) {
    for (std::size_t i = 0; i < out.n; i += every) f(i);
    if (also < out.n && also % every != 0) f(also);
  };
  out.momentum.assign(out.n, nan), out.momentum_scale.assign(scaled ? out.n : 0, nan);
  for_each_made([&](std::size_t i) {
    out.momentum[i] = Eigen::Map<const Eigen::Vector3d>(r.angular_momentum_W + 3 * i).norm();
    if (!scaled) return;
    double scale = 0.0;  // Σ |p_W × m v_W| bounded by |p_W| m |v_W|, + |H| of each body
    for (std::int64_t b = 0; b < out.bodies; ++b) {
      const std::size_t k = i * static_cast<std::size_t>(out.bodies) + static_cast<std::size_t>(b);
      scale += vector3(r.p_W, out, i, b).norm() * std::abs(r.mass[k]) * vector3(r.v_W, out, i, b).norm() +
               vector3(r.angular_momentum_O_W, out, i, b).norm();
    }
    out.momentum_scale[i] = scale;
  });
  // T − T(t0) = Σ work + Σ mass-flow energy + Σ motor work (SceneSimulation): each table's row width found once (0: a
  // table without a row per record, not summed)
  const auto width_of = [&](std::size_t size) {
    return size == 0 || out.n == 0 || size % out.n != 0 ? std::size_t{0} : size / out.n;
  };
  const std::size_t works = width_of(r.work_size), flows = width_of(r.mass_flow_energy_size),
                    motors = width_of(r.motor_work_size);
  const auto row_sum = [](const double* table, std::size_t width, std::size_t i) {
    return width == 0 ? 0.0 : std::accumulate(table + i * width, table + (i + 1) * width, 0.0);
  };
  if (r.kinetic_energy_size == out.n) {
    out.balance.assign(out.n, nan);
    for_each_made([&](std::size_t i) {
      out.balance[i] = r.kinetic_energy[i] - row_sum(r.work, works, i) - row_sum(r.mass_flow_energy, flows, i) -
                       row_sum(r.motor_work, motors, i);
    });
  }
  return out;
}

std::int64_t common_record_steps(std::int64_t record_every) { return std::lcm(record_every, std::int64_t{4}); }

CommonRecords common_records(const SimulationOptions& answer) {
  const std::int64_t m0 = common_record_steps(answer.record_every);
  const std::int64_t multiples = std::max<std::int64_t>(answer.steps, 0) / m0;
  const std::int64_t k = std::max<std::int64_t>((multiples + max_common_records - 1) / max_common_records, 1);
  CommonRecords out;
  out.steps_between = m0 * k;
  out.stride = static_cast<std::size_t>(out.steps_between / answer.record_every);
  out.last = static_cast<std::size_t>(multiples * m0 / answer.record_every);
  out.count = static_cast<std::size_t>((multiples + k - 1) / k) + 1;
  return out;
}

SimulationOptions coarse_options(const SimulationOptions& answer, int factor) {
  const std::int64_t m0 = common_record_steps(answer.record_every);
  SimulationOptions o = answer;
  o.dt = answer.dt * factor;
  o.steps = answer.steps / m0 * m0 / factor;
  o.record_every = common_records(answer).steps_between / factor;
  return o;
}

namespace {

// The common records of an estimate from the answer's records h (n of them): their grid, the last the answer has
// (j = 0 .. last, answer record grid.answer_record(j)) and its answer record.
struct CommonGrid {
  CommonRecords grid;
  std::size_t last = 0, last_i = 0;

  CommonGrid(const ErrorRecords& h, const SimulationOptions& answer) : grid(common_records(answer)) {
    last = grid.count - 1;
    while (last > 0 && grid.answer_record(last) >= h.n) --last;
    last_i = grid.answer_record(last);
  }
  std::size_t rows(const ErrorRecords& h) const { return h.n > 0 ? last + 1 : 0; }
};

// The rows of the common records (estimate_common) into `common` and, with_alone, into alone.table; a force the core
// cannot see into (`opaque`) leaves no record reliable in either.
template <bool with_alone>
void estimate_commons(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                      const SimulationOptions& answer, int order, const std::string& opaque,
                      std::optional<ErrorMeasure> only, const CommonGrid& at, CommonTable& common, Alone alone) {
  const double expected_ratio = std::ldexp(1.0, order);
  const auto hide = [&](CommonTable& table, std::size_t j) {
    if (is_reliable(table.verdict[j])) {
      table.verdict.set(j, "not verified: " + opaque +
                               " may switch inside a step, which the runs at h, 2h and 4h can all miss alike");
    }
    table.reliable_quantities[j] = 0;
  };
  for (std::size_t j = 0; j <= at.last && h.n > 0; ++j) {
    const std::size_t i = at.grid.answer_record(j);
    const char* problem = j >= h2.n   ? "step beyond the stability limit: the run at 2h diverged"
                          : j >= h4.n ? "step beyond the stability limit: the run at 4h diverged"
                                      : nullptr;
    estimate_common<with_alone>(h, h2, h4, i, j, step_of(i, answer), expected_ratio, problem, only, common, alone);
    if (opaque.empty()) continue;
    hide(common, j);
    if constexpr (with_alone) hide(*alone.table, j);
  }
}

// The estimate of every record of the answer h from its common rows `common` (estimate_commons): the growth past the
// Lyapunov time named, and the records between the common ones interpolated, those after them extrapolated.
GlobalErrorEstimate estimate_from_commons(const ErrorRecords& h, const SimulationOptions& answer, int order,
                                          const CommonGrid& at, CommonTable&& common) {
  GlobalErrorEstimate out;
  out.order = order, out.bodies = h.bodies;
  const CommonRecords& grid = at.grid;
  const std::size_t stride = grid.stride;  // answer records per common record
  const std::size_t last = at.last, last_i = at.last_i;
  name_exponential_growth(common, h.t, grid);
  const CommonVerdicts verdicts(std::move(common.verdict), out.verdict);
  out.verdict.reserve(h.n);
  const std::uint32_t between = out.verdict.add_text("interpolated between the reliable records before and after it");
  std::uint32_t after = 0, none = 0;  // the verdicts after the last common record and without an estimate
  if (last > 0 && h.n - 1 > last_i) {
    after = out.verdict.add_text("extrapolated from the reliable record at t = " + seconds(h.t[last_i]));
  } else if (h.n > 1 && last == 0) {
    none = out.verdict.add_text("no estimate: fewer than " + std::to_string(common_record_steps(answer.record_every)) +
                                " steps (the 2h and 4h runs have a state only every lcm(record_every, 4) steps)");
  }
  std::vector<RowSource> sources(h.n);
  out.reliable_quantities.assign(h.n, 0);  // a record between or after the common ones is not checked
  for (std::size_t i = 0; i < h.n; ++i) {
    // the common record at i (the last one where i is last_i), else the one before i
    const std::size_t j = i == last_i ? last : i / stride;
    RowSource& s = sources[i];
    if (i == grid.answer_record(j) && j <= last) {
      s = {RowSource::common, j, j, 1.0, 0.0};
      out.verdict.push_back_text(verdicts.text[j]);
      out.reliable_quantities[i] = common.reliable_quantities[j];
    } else if (i < last_i) {  // between common records j and j + 1
      const double tj = h.t[grid.answer_record(j)], tk = h.t[grid.answer_record(j + 1)];
      const double w = (h.t[i] - tj) / (tk - tj);
      s = {RowSource::blend, j, j + 1, 1.0 - w, w};
      out.verdict.push_back_text(verdicts.first_unreliable_or(j, j + 1, between));
    } else if (last > 0) {  // after the last common record: linear growth from t0
      const double t0 = h.t[0], tc = h.t[last_i];
      const double w = (h.t[i] - t0) / (tc - t0);
      s = {RowSource::scaled, last, last, 1.0 - w, w};
      out.verdict.push_back_text(verdicts.first_unreliable_or(last, last, after));
    } else {  // no common record but the first: no estimate (NaN)
      out.verdict.push_back_text(none);
    }
  }
  if (stride == 1 && h.n == last + 1) {
    take_rows(out, std::move(common));
  } else {
    size_for_records(out, h.n, h.bodies);
    put_rows(out, common, sources);
  }
  return out;
}

}  // namespace

GlobalErrorEstimate estimate_global_error(const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4,
                                          const SimulationOptions& answer, int order, const std::string& opaque,
                                          std::optional<ErrorMeasure> only) {
  if (order < 1) throw_invalid("order", "an integer >= 1", order);
  const CommonGrid at(h, answer);
  CommonTable common(at.rows(h), static_cast<std::size_t>(std::max<std::int64_t>(h.bodies, 0)), order);
  estimate_commons<false>(h, h2, h4, answer, order, opaque, only, at, common, Alone{nullptr, ErrorMeasure::attitude});
  return estimate_from_commons(h, answer, order, at, std::move(common));
}

std::pair<GlobalErrorEstimate, GlobalErrorEstimate> estimate_global_error_and_alone(
    const ErrorRecords& h, const ErrorRecords& h2, const ErrorRecords& h4, const SimulationOptions& answer, int order,
    ErrorMeasure measure) {
  if (order < 1) throw_invalid("order", "an integer >= 1", order);
  const CommonGrid at(h, answer);
  const auto nb = static_cast<std::size_t>(std::max<std::int64_t>(h.bodies, 0));
  CommonTable common(at.rows(h), nb, order), alone(at.rows(h), nb, order);
  estimate_commons<true>(h, h2, h4, answer, order, {}, std::nullopt, at, common, Alone{&alone, measure});
  return {estimate_from_commons(h, answer, order, at, std::move(common)),
          estimate_from_commons(h, answer, order, at, std::move(alone))};
}

GlobalErrorEstimate no_estimate(std::size_t n, std::int64_t bodies, int order, std::string_view why) {
  GlobalErrorEstimate out;
  out.order = order, out.bodies = bodies;
  size_for_records(out, n, bodies);
  out.verdict.assign(n, why);
  out.reliable_quantities.assign(n, 0);
  return out;
}

GlobalErrorEstimate round_off_estimate(const ErrorRecords& h, const SimulationOptions& answer) {
  GlobalErrorEstimate out;
  out.order = 0, out.bodies = h.bodies;
  size_for_records(out, h.n, h.bodies);
  const auto nb = static_cast<std::size_t>(std::max<std::int64_t>(h.bodies, 0));
  for (std::size_t i = 0; i < h.n; ++i) {
    const std::int64_t steps = step_of(i, answer);
    for (std::size_t b = 0; b < nb; ++b) {
      const auto body = static_cast<std::int64_t>(b);
      out.attitude[i * nb + b] = round_off_bound(1.0, steps);
      out.angular_velocity[i * nb + b] = round_off_bound(vector3(h.w_B, h, i, body).norm(), steps);
      out.position[i * nb + b] = round_off_bound(vector3(h.p_W, h, i, body).norm(), steps);
      out.velocity[i * nb + b] = round_off_bound(vector3(h.v_W, h, i, body).norm(), steps);
    }
    out.energy[i] = round_off_bound(energy_size_of(h, i), steps);
    const double momentum = h.momentum_scale.empty() ? h.momentum[i] : h.momentum_scale[i];
    out.angular_momentum[i] = round_off_bound(momentum, steps);
  }
  out.verdict.assign(h.n, reliable_verdict);
  out.reliable_quantities.assign(h.n, every_measure);
  return out;
}

}  // namespace rigiddyn
