#include "text_table.h"

#include <algorithm>

namespace fooball::cli {

namespace {

/// Characters on screen for UTF-8 text: every byte but the continuation bytes 10xxxxxx.
std::size_t displayWidth(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

}  // namespace

void TextTable::print(std::ostream& out, int indent) const {
  std::vector<std::size_t> columnWidths;
  for (const auto& line : lines_) {
    const auto* cells = std::get_if<std::vector<std::string>>(&line);
    if (cells == nullptr) continue;
    columnWidths.resize(std::max(columnWidths.size(), cells->size()), 0);
    for (std::size_t column = 0; column < cells->size(); ++column) {
      columnWidths[column] = std::max(columnWidths[column], displayWidth((*cells)[column]));
    }
  }

  const std::string indentText(static_cast<std::size_t>(std::max(indent, 0)), ' ');
  for (const auto& line : lines_) {
    const auto* cells = std::get_if<std::vector<std::string>>(&line);
    if (cells == nullptr) {
      out << std::get<std::string>(line) << '\n';
      continue;
    }
    std::string text = indentText;
    for (std::size_t column = 0; column < cells->size(); ++column) {
      const std::string& cell = (*cells)[column];
      text += cell;
      if (column + 1 < cells->size()) {
        text.append(columnWidths[column] - displayWidth(cell) + 2, ' ');
      }
    }
    // A trailing empty cell would leave padding at the end of the line.
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << '\n';
  }
}

}  // namespace fooball::cli
