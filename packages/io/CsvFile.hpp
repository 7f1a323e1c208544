#pragma once
// Comma-separated tables: a history file that grows by one row per step (opened and closed
// for every row, so it is complete up to the last finished step), and whole tables written
// at once.  Numbers are written in the shortest form that reads back exactly.

#include <Teuchos_Comm.hpp>

#include <string>
#include <vector>

namespace impm {

class CsvHistory {
 public:
  // Creates (truncates) the file and writes the header.  With keepThrough >= 0 (a restart)
  // an existing file with the same header keeps its rows whose first column (the step) is at
  // most keepThrough, and the comment lines among them, and is continued (continued() says
  // whether it was).  Each note is then written as a comment line, "# note", where the new
  // rows begin: the file records what a restart changed at the step it changed it (csv
  // readers skip such lines with comment='#').
  CsvHistory(const std::string& path, const std::vector<std::string>& columns, int keepThrough = -1,
             const std::vector<std::string>& notes = {});
  void append(const std::vector<double>& row) const;
  const std::vector<std::string>& columns() const { return columns_; }
  const std::string& path() const { return path_; }
  bool continued() const { return continued_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  bool continued_ = false;
};

// The rows of a table whose column c is values[c]: "v,v,...\n" per row.
std::string formatCsvRows(const std::vector<std::vector<double>>& values);

// columns[c] names values[c][row].
void writeCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& values);

// Collective: every rank passes a consecutive block of the table's rows, rank 0 the first
// block, rank 1 the next, and so on (a rank may have none).  Each rank formats and writes its
// own bytes at its offset (MPI-IO), so the file is the same as writeCsvTable's of the whole
// table, and the work is shared by the ranks.
void writeCsvTableCollectively(const std::string& path, const Teuchos::Comm<int>& comm,
                               const std::vector<std::string>& columns,
                               const std::vector<std::vector<double>>& localValues);

}  // namespace impm
