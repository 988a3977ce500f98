// A table printed as aligned text for people or as CSV for programs: one code path per tool.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace kutlog::tools {

enum class Format { text, csv, markdown };

// A CSV field as RFC 4180 writes it: a field holding a comma, a quote or a line break (a domain
// such as "[-1, 1]") is quoted, with its quotes doubled, so that it stays one field; any other
// field is written as it is.
inline std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}

  void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }

  void print(Format format, std::FILE* out = stdout) const {
    if (format == Format::csv) {
      print_csv_row(header_, out);
      for (const auto& row : rows_) print_csv_row(row, out);
      return;
    }
    if (format == Format::markdown) {
      print_markdown_row(header_, out);
      print_markdown_row(std::vector<std::string>(header_.size(), "---"), out);
      for (const auto& row : rows_) print_markdown_row(row, out);
      return;
    }
    std::vector<std::size_t> widths(header_.size());
    for (std::size_t i = 0; i < header_.size(); ++i) widths[i] = header_[i].size();
    for (const auto& row : rows_)
      for (std::size_t i = 0; i < row.size() && i < widths.size(); ++i)
        widths[i] = std::max(widths[i], row[i].size());
    print_text_row(header_, widths, out);
    for (const auto& row : rows_) print_text_row(row, widths, out);
  }

 private:
  static void print_csv_row(const std::vector<std::string>& row, std::FILE* out) {
    for (std::size_t i = 0; i < row.size(); ++i)
      fmt::print(out, "{}{}", i ? "," : "", csv_field(row[i]));
    fmt::print(out, "\n");
  }
  static void print_markdown_row(const std::vector<std::string>& row, std::FILE* out) {
    fmt::print(out, "| {} |\n", fmt::join(row, " | "));
  }
  static void print_text_row(const std::vector<std::string>& row,
                             const std::vector<std::size_t>& widths, std::FILE* out) {
    for (std::size_t i = 0; i < row.size(); ++i)
      fmt::print(out, "{}{:>{}}", i ? "  " : "", row[i], widths[i]);
    fmt::print(out, "\n");
  }

  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// The --format option's value ("text", "csv" or "markdown") as a Format.
inline Format parse_format(const std::string& name) {
  return name == "csv" ? Format::csv : name == "markdown" ? Format::markdown : Format::text;
}

}  // namespace kutlog::tools
