// A table printed as aligned text for people or as CSV for programs: one code path per tool.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace kutlog::tools {

enum class Format { text, csv, markdown };

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
      std::fprintf(out, "%s%s", i ? "," : "", row[i].c_str());
    std::fputc('\n', out);
  }
  static void print_markdown_row(const std::vector<std::string>& row, std::FILE* out) {
    for (const std::string& cell : row) std::fprintf(out, "| %s ", cell.c_str());
    std::fputs("|\n", out);
  }
  static void print_text_row(const std::vector<std::string>& row,
                             const std::vector<std::size_t>& widths, std::FILE* out) {
    for (std::size_t i = 0; i < row.size(); ++i)
      std::fprintf(out, "%s%*s", i ? "  " : "", static_cast<int>(widths[i]), row[i].c_str());
    std::fputc('\n', out);
  }

  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// The --format option's value ("text", "csv" or "markdown") as a Format.
inline Format parse_format(const std::string& name) {
  return name == "csv" ? Format::csv : name == "markdown" ? Format::markdown : Format::text;
}

// printf-style formatting of one cell.
template <typename... Args>
std::string cell(const char* format, Args... args) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

}  // namespace kutlog::tools
