// main() for every benchmark: runs the registered benchmarks with the console reporter, then
// prints the rigiddyn/baseline ratio of each case (see bench_common.hpp for the naming), or why a case
// has none (a side that stopped with an error).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Key {
  std::string case_name;  // "<case>/<args>"
  std::string kind;       // "rigiddyn" or "baseline"
};

// "rotate:rigiddyn/1000000" -> {"rotate/1000000", "rigiddyn"}
bool parse(const std::string& name, Key& key) {
  const auto colon = name.find(':');
  if (colon == std::string::npos) return false;
  const auto slash = name.find('/', colon);
  key.kind = name.substr(colon + 1, slash == std::string::npos ? std::string::npos : slash - colon - 1);
  key.case_name = name.substr(0, colon) + (slash == std::string::npos ? "" : name.substr(slash));
  return key.kind == "rigiddyn" || key.kind == "baseline";
}

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      Key key;
      if (run.run_type != Run::RT_Iteration || !parse(run.benchmark_name(), key)) continue;
      if (run.error_occurred) {  // a case that stopped (SkipWithError) has no time to compare
        stopped_[key.case_name] = key.kind + " stopped: " + run.error_message;
        continue;
      }
      double items = 1.0;
      const auto it = run.counters.find("items_per_second");
      // items_per_second = items / real time, so ns per item = 1e9 / items_per_second
      if (it != run.counters.end() && it->second.value > 0) {
        ns_per_op_[key.case_name][key.kind] = 1e9 / it->second.value;
      } else {
        // GetAdjustedRealTime is in run.time_unit, GetTimeUnitMultiplier that unit per second
        ns_per_op_[key.case_name][key.kind] =
            run.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(run.time_unit) * 1e9 / items;
      }
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n");
    for (const auto& [case_name, why] : stopped_) {
      std::printf("ratio %s: not measured (%s)\n", case_name.c_str(), why.c_str());
    }
    for (const auto& [case_name, by_kind] : ns_per_op_) {
      if (stopped_.count(case_name)) continue;
      const auto r = by_kind.find("rigiddyn");
      const auto b = by_kind.find("baseline");
      if (r == by_kind.end() || b == by_kind.end()) continue;
      std::printf("ratio %s: rigiddyn %.3f ns/op, baseline %.3f ns/op, rigiddyn/baseline = %.3f\n",
                  case_name.c_str(), r->second, b->second, r->second / b->second);
    }
    std::fflush(stdout);
  }

 private:
  std::map<std::string, std::map<std::string, double>> ns_per_op_;
  std::map<std::string, std::string> stopped_;  // case → which side stopped, and why
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
