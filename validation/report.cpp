#include "validation/report.h"

#include <algorithm>
#include <iomanip>

#include <nlohmann/json.hpp>

namespace voxgi::validation {

nlohmann::json toJson(const std::vector<StageReport>& reports) {
  nlohmann::json stages = nlohmann::json::array();
  bool pass = true;
  for (const StageReport& s : reports) {
    nlohmann::json buffers = nlohmann::json::array();
    for (const BufferReport& b : s.buffers)
      buffers.push_back({{"buffer", b.buffer},
                         {"metric", b.metric},
                         {"tolerance", b.tolerance},
                         {"reason", b.reason},
                         {"status", b.status},
                         {"elements", b.elements},
                         {"differing", b.differing},
                         {"fraction", b.fraction},
                         {"max_abs_diff", b.maxAbsDiff},
                         {"max_ulp", b.maxUlp},
                         {"ties", b.ties},
                         {"non_ties", b.nonTies},
                         {"unclassified", b.unclassified},
                         {"worst_element", b.worstElement},
                         {"pass", b.pass}});
    stages.push_back({{"stage", s.stage},
                      {"skipped", s.skipped},
                      {"cpu_seconds", s.cpuSeconds},
                      {"gpu_seconds", s.gpuSeconds},
                      {"pass", s.pass},
                      {"buffers", buffers}});
    pass &= s.pass;
  }
  return {{"pass", pass}, {"stages", stages}};
}

void printReport(std::ostream& out, const std::vector<StageReport>& reports) {
  for (const StageReport& s : reports) {
    if (!s.skipped.empty()) {
      out << "stage " << s.stage << ": " << s.skipped << "\n";
      continue;
    }
    out << "stage " << s.stage << ": " << (s.pass ? "PASS" : "FAIL") << "  (cpu " << std::fixed
        << std::setprecision(3) << s.cpuSeconds << " s, gpu " << s.gpuSeconds << " s)\n";
    // Columns as wide as the longest buffer name and metric.
    int nameWidth = 8, metricWidth = 8;
    for (const BufferReport& b : s.buffers) {
      nameWidth = std::max(nameWidth, int(b.buffer.size()) + 2);
      metricWidth = std::max(metricWidth, int(b.metric.size()) + 2);
    }
    out << "  " << std::left << std::setw(nameWidth) << "buffer" << std::setw(metricWidth)
        << "metric" << std::right << std::setw(12) << "max |diff|" << std::setw(12) << "max ULP"
        << std::setw(11) << "differing" << std::setw(11) << "fraction" << std::setw(7) << "ties"
        << std::setw(10) << "non-ties"
        << "  result\n";
    for (const BufferReport& b : s.buffers) {
      out << "  " << std::left << std::setw(nameWidth) << b.buffer << std::setw(metricWidth)
          << b.metric;
      if (b.status != "compared") {
        out << b.status << (b.pass ? "" : "  FAIL") << "\n";
        continue;
      }
      out << std::right << std::setw(12) << std::setprecision(3) << std::scientific << b.maxAbsDiff
          << std::fixed << std::setprecision(0) << std::setw(12) << b.maxUlp << std::setw(11)
          << b.differing << std::setw(11) << std::setprecision(6) << b.fraction << std::setw(7)
          << b.ties << std::setw(10) << b.nonTies + b.unclassified << "  "
          << (b.pass ? "pass" : "FAIL") << "\n";
    }
  }
}

}  // namespace voxgi::validation
