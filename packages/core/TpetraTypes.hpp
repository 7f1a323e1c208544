#pragma once
// Tpetra types used for grid degrees of freedom.  Debian's Trilinos instantiates Tpetra only
// for the default template arguments, so every type comes from Tpetra::Map<>.

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_FEMultiVector.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace impm {

using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using CrsGraph = Tpetra::CrsGraph<LO, GO, Node>;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using FECrsGraph = Tpetra::FECrsGraph<LO, GO, Node>;
using FECrsMatrix = Tpetra::FECrsMatrix<double, LO, GO, Node>;
using FEMultiVector = Tpetra::FEMultiVector<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using Vector = Tpetra::Vector<double, LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

// The values of x (on A's row map) on A's column map, as a product A x reads them.
// Collective.
inline Vector onColumns(const CrsMatrix& A, const Vector& x) {
  Vector columns(A.getColMap());
  if (const auto importer = A.getGraph()->getImporter(); importer.is_null())
    Tpetra::deep_copy(columns, x);  // the column map is the row map
  else
    columns.doImport(x, *importer, Tpetra::INSERT);
  return columns;
}

}  // namespace impm
