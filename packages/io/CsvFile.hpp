#pragma once
// Comma-separated tables: a history file that grows by one row per step (opened and closed
// for every row, so it is complete up to the last finished step), and whole tables written
// at once.  Numbers are written in the shortest form that reads back exactly.

#include <string>
#include <vector>

namespace impm {

class CsvHistory {
 public:
  // Creates (truncates) the file and writes the header.
  CsvHistory(const std::string& path, const std::vector<std::string>& columns);
  void append(const std::vector<double>& row) const;
  const std::vector<std::string>& columns() const { return columns_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
};

// columns[c] names values[c][row].
void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values);

}  // namespace impm
