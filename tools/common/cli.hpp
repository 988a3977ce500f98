// Shared by the kutlog tools: argument errors are one line on stderr and exit status 2.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>

namespace kutlog::tools {

inline constexpr int kExitBadArguments = 2;

// --format, the table's output format (text, csv or markdown; see table.hpp's parse_format).
inline CLI::Option* add_format_option(CLI::App& app, std::string& format_name) {
  return app.add_option("--format", format_name, "Output format: text, csv or markdown")
      ->check(CLI::IsMember({"text", "csv", "markdown"}))
      ->capture_default_str();
}

// Parses the command line, then runs `body`. --help prints the usage and exits 0; a bad
// argument, or a std::invalid_argument thrown by the body (an invalid model parameter), prints
// "<tool>: error: <reason>" and exits 2; any other failure exits 1.
inline int run_tool(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::fprintf(stderr, "%s: error: %s (see --help)\n", app.get_name().c_str(), error.what());
    return kExitBadArguments;
  }
  try {
    return body();
  } catch (const std::invalid_argument& error) {
    std::fprintf(stderr, "%s: error: %s\n", app.get_name().c_str(), error.what());
    return kExitBadArguments;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: failed: %s\n", app.get_name().c_str(), error.what());
    return 1;
  }
}

}  // namespace kutlog::tools
