// The common records of a global error estimate (simulate/global_error.hpp common_records and coarse_options): t0,
// every lcm(record_every, 4) steps up to max_common_records after t0, further apart in longer runs, and always the
// last multiple of lcm(record_every, 4); the runs at 2h and 4h record exactly there.
#include "rigiddyn/simulate/global_error.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

SimulationOptions answer_of(std::int64_t steps, std::int64_t record_every) {
  SimulationOptions o;
  o.dt = 0.01, o.steps = steps, o.record_every = record_every;
  return o;
}

// The steps at which a run of options o records: 0, every record_every-th and the last (run_loop.hpp)
std::vector<std::int64_t> recorded_steps(const SimulationOptions& o) {
  std::vector<std::int64_t> out;
  for (std::int64_t i = 0; i <= o.steps; i += o.record_every) out.push_back(i);
  if (out.back() != o.steps) out.push_back(o.steps);
  return out;
}

TEST(CommonRecords, EveryMultipleOfLcmUpToTheCapThenFurtherApartAndTheLast) {
  for (const std::int64_t record_every : {1, 3, 4, 6, 100}) {
    const std::int64_t m0 = std::lcm(record_every, std::int64_t{4});
    for (const std::int64_t multiples : {0, 1, 7, 1023, 1024, 1025, 2048, 3074, 45000}) {
      for (const std::int64_t extra : {std::int64_t{0}, m0 - 1}) {
        const std::int64_t steps = multiples * m0 + extra;
        if (steps == 0) continue;
        SCOPED_TRACE("record_every " + std::to_string(record_every) + ", steps " + std::to_string(steps));
        const SimulationOptions answer = answer_of(steps, record_every);
        const CommonRecords common = common_records(answer);
        EXPECT_LE(common.count, static_cast<std::size_t>(max_common_records) + 1);
        EXPECT_EQ(common.steps_between % m0, 0);
        if (multiples <= max_common_records) {  // every multiple of m0
          EXPECT_EQ(common.steps_between, m0);
          EXPECT_EQ(common.count, static_cast<std::size_t>(multiples) + 1);
        } else {  // as few further apart as leave at most the cap
          EXPECT_GT(common.count, static_cast<std::size_t>(max_common_records) / 2);
        }
        EXPECT_EQ(common.answer_record(common.count - 1) * static_cast<std::size_t>(record_every),
                  static_cast<std::size_t>(multiples * m0));  // the last: the last multiple of m0
        // the runs at 2h and 4h record at the answer's common records, in order, and nowhere else
        const std::vector<std::int64_t> answer_steps = recorded_steps(answer);
        for (const int factor : {2, 4}) {
          const SimulationOptions coarse = coarse_options(answer, factor);
          EXPECT_DOUBLE_EQ(coarse.dt, answer.dt * factor);
          const std::vector<std::int64_t> coarse_steps = recorded_steps(coarse);
          ASSERT_EQ(coarse_steps.size(), common.count);
          for (std::size_t j = 0; j < common.count; ++j) {
            EXPECT_EQ(coarse_steps[j] * factor, answer_steps[common.answer_record(j)]) << "common record " << j;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace rigiddyn
