#pragma once
// What the framework knows of a particle field, declared once with the field: its name, its
// shape, which columns it writes to the particle tables, and whether it is checkpointed,
// migrated between ranks and kept at two time levels.  Resizing, migration, output and
// checkpoints walk these declarations (ParticleSet::forEachField); none lists fields by hand.

#include <string>
#include <vector>

namespace impm {

// scalar: 1 component; vector: Dim; tensor: Dim x Dim, row-major (a, b) at a * Dim + b;
// symmetric3x3: the 6 independent components of a symmetric 3 x 3 tensor (the elastic left
// Cauchy-Green tensor of plane-strain plasticity has an out-of-plane part) in the order
// xx, yy, zz, xy, yz, xz.  corners: the 2^Dim corners of a particle domain, component
// c * Dim + d, counter-clockwise in 2-D; faces: one value per face (2-D: edge k from corner k
// to corner k + 1).
enum class FieldShape { scalar, vector, tensor, symmetric3x3, corners, faces };

template <int Dim>
constexpr int componentCount(FieldShape shape) {
  switch (shape) {
    case FieldShape::scalar:
      return 1;
    case FieldShape::vector:
      return Dim;
    case FieldShape::tensor:
      return Dim * Dim;
    case FieldShape::symmetric3x3:
      return 6;
    case FieldShape::corners:
      return (1 << Dim) * Dim;
    case FieldShape::faces:
      return 2 * Dim;
  }
  return 0;
}

// One written component: its index, its CSV column name and its Exodus element-variable
// name ("" when it is not an element variable: reference positions are the points'
// coordinates, displacements their nodal fields, ids their numbering).
struct OutputColumn {
  int component = 0;
  std::string csv, exodus;
};

struct FieldSpec {
  std::string name;  // unique; what Output/Fields and the checkpoint call it
  FieldShape shape = FieldShape::scalar;
  std::string doc;                    // one line for the user guide
  std::vector<OutputColumn> columns;  // the components written; empty: not an output
  bool checkpoint = true;             // saved at full precision and restored on restart
  bool migrate = true;                // travels with its particle to another rank
  // A trial value exists during a step (state at n + 1, the stored one being at n): the
  // framework commits it when the step is accepted and drops it on a cutback.
  bool twoLevels = false;

  bool output() const { return !columns.empty(); }
};

// The default columns of a field: `name` (scalars; vectors and tensors in 1-D); name_x,
// name_y for 2-D vectors (Exodus: nameX, nameY, which ParaView groups into a vector);
// name_xx, name_xy, ... for tensors; name_xx, name_yy, name_zz, name_xy, name_yz, name_xz
// for symmetric 3 x 3 tensors; name1_x, name1_y, ... for corners; name_1, ... for faces.
template <int Dim>
std::vector<OutputColumn> defaultColumns(const std::string& name, FieldShape shape);

// True for names that every output format accepts: a letter, then letters, digits and '_'.
bool isFieldName(const std::string& name);

}  // namespace impm
