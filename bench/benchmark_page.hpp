// The benchmark page of one machine (docs/benchmarks/<machine>.md), written from one run's
// Google Benchmark JSON: where the figures come from (machine, compiler and flags, commit,
// date, the exact command), then each ratio table with what it compares.
#pragma once

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "ratio_report.hpp"

namespace kutlog::bench {

// The page's file name without ".md": the CPU model in lowercase words joined by '-' (without
// "(R)", "(TM)", "CPU", "Processor", "<n>-Core" and the clock after '@'), then the best arch
// kutlog ran, e.g. "Intel(R) Xeon(R) Processor" with avx512 -> "intel-xeon-avx512".
std::string machine_slug(const nlohmann::json& context);

// Writes the page of the run read by run.load_json().
void write_benchmark_page(std::FILE* out, const RatioCollector& run);

}  // namespace kutlog::bench
