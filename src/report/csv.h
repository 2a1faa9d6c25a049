// A small reader for the plain CSV files hexgait writes (no quoting, comma separated, one
// header line), with errors that name the file, the line and the column.
#pragma once

#include <string>
#include <vector>

namespace hexgait {

// Text from outside (a gait's file name, a group) as one field of such a file: the separator,
// a quote and line breaks, which it cannot represent, become '_', so every row keeps its columns
// and reads back.
std::string CsvText(std::string text);

class CsvTable {
 public:
  // Reads `path`; requires that the header holds every column in `required` (other columns
  // are allowed, so a newer writer can add some). Throws InputError.
  static CsvTable Read(const std::string& path, const std::vector<std::string>& required);

  size_t rows() const { return cells_.size(); }
  const std::string& Text(size_t row, const std::string& column) const;
  double Number(size_t row, const std::string& column) const;  // finite or not, but a number
  // "1"/"true" or "0"/"false".
  bool Bool(size_t row, const std::string& column) const;

 private:
  size_t Column(const std::string& name) const;
  [[noreturn]] void Fail(size_t row, const std::string& column, const std::string& what) const;

  std::string path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<int> line_;  // file line of each row, for messages
};

}  // namespace hexgait
