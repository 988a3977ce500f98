// kutlog-sample: directions drawn from the normalized F_kutlog lobe by the SIMD sampler
// (kutlog/sampling.hpp), one sample per row: x, y, z in the local frame (z the normal for
// microfacet half vectors, the mirror direction for phong), then the pdf over solid angle.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/cli.hpp"
#include "common/table.hpp"
#include "kutlog/sampling.hpp"

namespace {

constexpr std::size_t kChunk = 4096;  // samples drawn per call of the sampler

struct Options {
  double n = 100, Q = 0.5;
  int k = 3;
  std::string use = "microfacet", format = "csv";
  std::size_t count = 1000;
  std::uint64_t seed = 1;
};

int run(const Options& options) {
  const kutlog::LobeSampler sampler(options.n, options.k, options.Q,
                                    options.use == "phong" ? kutlog::LobeUse::phong
                                                           : kutlog::LobeUse::microfacet);
  std::mt19937_64 engine(options.seed);
  const auto uniform = [&] { return float(engine() >> 40) * 0x1p-24f; };  // [0, 1)
  const bool csv = options.format == "csv";
  kutlog::tools::Table table({"x", "y", "z", "pdf"});
  std::vector<float> u1(kChunk), u2(kChunk), x(kChunk), y(kChunk), z(kChunk), pdf(kChunk);
  std::vector<float> record;
  for (std::size_t done = 0; done < options.count; done += kChunk) {
    const std::size_t count = std::min(kChunk, options.count - done);
    for (std::size_t i = 0; i < count; ++i) u1[i] = uniform(), u2[i] = uniform();
    sampler.sample(u1.data(), u2.data(), {x.data(), y.data(), z.data(), pdf.data()}, count);
    if (csv) {
      for (std::size_t i = 0; i < count; ++i)
        table.add_row({fmt::format("{:.9g}", x[i]), fmt::format("{:.9g}", y[i]),
                       fmt::format("{:.9g}", z[i]), fmt::format("{:.9g}", pdf[i])});
      continue;
    }
    record.clear();
    for (std::size_t i = 0; i < count; ++i)
      record.insert(record.end(), {x[i], y[i], z[i], pdf[i]});
    if (std::fwrite(record.data(), sizeof(float), record.size(), stdout) != record.size())
      throw std::runtime_error("cannot write to stdout");
  }
  if (csv) table.print(kutlog::tools::Format::csv);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Draw directions from the normalized F_kutlog lobe with kutlog's SIMD sampler, one sample\n"
      "per row: x, y, z in the local frame (z = the normal for --use microfacet, whose samples\n"
      "are half vectors; z = the mirror direction for --use phong), then the pdf over solid\n"
      "angle. --format csv writes a header and text rows; --format binary writes, per sample,\n"
      "four float32 (x, y, z, pdf) in the machine's byte order, no header.",
      "kutlog-sample");
  Options options;
  app.add_option("--n", options.n, "Exponent n, finite > 0")->capture_default_str();
  app.add_option("--k", options.k, "Power k, integer in [1, 64]")->capture_default_str();
  app.add_option("--q", options.Q, "Anchor Q, in (0, 1)")->capture_default_str();
  app.add_option("--use", options.use, "microfacet or phong")
      ->check(CLI::IsMember({"microfacet", "phong"}))
      ->capture_default_str();
  app.add_option("--count", options.count, "Number of samples, >= 1")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40))
      ->capture_default_str();
  app.add_option("--seed", options.seed, "Seed of the uniform numbers (mt19937_64)")
      ->capture_default_str();
  app.add_option("--format", options.format, "csv or binary")
      ->check(CLI::IsMember({"csv", "binary"}))
      ->capture_default_str();
  return kutlog::tools::run_tool(app, argc, argv, [&] { return run(options); });
}
