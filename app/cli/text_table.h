#pragma once

#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace fooball::cli {

/// Human-readable aligned columns: every row's cells are padded to the widest cell of their
/// column (counted in characters, not UTF-8 bytes), two spaces apart. Free lines (headings)
/// may sit between rows without affecting the widths, so rows under different headings line up.
class TextTable {
 public:
  void addRow(std::vector<std::string> cells) { lines_.emplace_back(std::move(cells)); }
  void addLine(std::string text) { lines_.emplace_back(std::move(text)); }

  /// Writes every line, each row preceded by `indent` spaces.
  void print(std::ostream& out, int indent = 0) const;

 private:
  std::vector<std::variant<std::string, std::vector<std::string>>> lines_;
};

}  // namespace fooball::cli
