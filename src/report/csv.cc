#include "report/csv.h"

#include <cstdlib>
#include <sstream>

#include "util/error.h"
#include "util/json_file.h"

namespace hexgait {

std::string CsvText(std::string text) {
  for (char& c : text) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '_';
  }
  return text;
}
namespace {

std::vector<std::string> SplitLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

CsvTable CsvTable::Read(const std::string& path, const std::vector<std::string>& required) {
  CsvTable table;
  table.path_ = path;
  std::istringstream in(ReadTextFile(path));
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (table.header_.empty()) {
      table.header_ = SplitLine(line);
      for (const std::string& name : required) table.Column(name);
      continue;
    }
    std::vector<std::string> cells = SplitLine(line);
    if (cells.size() != table.header_.size()) {
      throw InputError(path + " line " + std::to_string(number) + ": " +
                       std::to_string(cells.size()) + " fields, the header has " +
                       std::to_string(table.header_.size()));
    }
    table.cells_.push_back(std::move(cells));
    table.line_.push_back(number);
  }
  return table;
}

size_t CsvTable::Column(const std::string& name) const {
  for (size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return i;
  }
  throw InputError(path_ + ": no column '" + name + "' in the header");
}

void CsvTable::Fail(size_t row, const std::string& column, const std::string& what) const {
  throw InputError(path_ + " line " + std::to_string(line_[row]) + ", column '" + column +
                   "': " + what);
}

const std::string& CsvTable::Text(size_t row, const std::string& column) const {
  return cells_[row][Column(column)];
}

double CsvTable::Number(size_t row, const std::string& column) const {
  const std::string& text = Text(row, column);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    Fail(row, column, "'" + text + "' is not a number");
  return value;
}

bool CsvTable::Bool(size_t row, const std::string& column) const {
  const std::string& text = Text(row, column);
  if (text == "1" || text == "true") return true;
  if (text == "0" || text == "false") return false;
  Fail(row, column, "'" + text + "' is not 0/1 or true/false");
}

}  // namespace hexgait
