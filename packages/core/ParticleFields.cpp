#include <cctype>

#include "core/Axes.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

namespace {

FieldSpec field(const std::string& name, FieldShape shape, const std::string& doc) {
  FieldSpec s;
  s.name = name, s.shape = shape, s.doc = doc;
  return s;
}

// Columns that are positions or displacements of the Exodus points, not element variables.
std::vector<OutputColumn> csvOnly(std::vector<OutputColumn> columns) {
  for (auto& c : columns)
    c.exodus.clear();
  return columns;
}

}  // namespace

template <int Dim>
std::vector<OutputColumn> defaultColumns(const std::string& name, FieldShape shape) {
  std::vector<OutputColumn> out;
  switch (shape) {
    case FieldShape::scalar:
      out.push_back({0, name, name});
      break;
    case FieldShape::vector:
      for (int d = 0; d < Dim; ++d)
        out.push_back({d, Dim == 1 ? name : name + "_" + axisName(d), name + referenceAxisName(d)});
      break;
    case FieldShape::tensor:
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) {
          const std::string n = Dim == 1 ? name : name + "_" + axisName(a) + axisName(b);
          out.push_back({a * Dim + b, n, n});
        }
      break;
    case FieldShape::symmetric3x3: {
      const char* const pairs[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
      for (int c = 0; c < 6; ++c)
        out.push_back({c, name + "_" + pairs[c], name + "_" + pairs[c]});
      break;
    }
    case FieldShape::corners:
      for (int c = 0; c < (1 << Dim); ++c)
        for (int d = 0; d < Dim; ++d) {
          const std::string n = name + std::to_string(c + 1) + "_" + axisName(d);
          out.push_back({c * Dim + d, n, n});
        }
      break;
    case FieldShape::faces:
      for (int f = 0; f < 2 * Dim; ++f)
        out.push_back({f, name + "_" + std::to_string(f + 1), name + "_" + std::to_string(f + 1)});
      break;
  }
  return out;
}

bool isFieldName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0])))
    return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      return false;
  return true;
}

// The framework's fields.  Derived fields (strain, J, sigma_zz) are recomputed before every
// output, so they are neither checkpointed nor migrated.  The external force is set before
// every step but not checkpointed; it migrates, because loads that stay the same numbers are
// not set again (Bodies::applyLoads).  Column names and order are the output contract of
// doc/design.md.
template <int Dim>
BuiltinFields<Dim>::BuiltinFields() {
  const auto vector = FieldShape::vector;
  const auto tensor = FieldShape::tensor;
  const auto scalar = FieldShape::scalar;
  id = field("id", scalar, "global particle id (rows are sorted by it)");
  id.columns = {{0, "id", ""}};
  X = field("X", vector, "reference position");
  X.columns = csvOnly(defaultColumns<Dim>("X", vector));
  if (Dim > 1)  // X, Y, Z
    for (int d = 0; d < Dim; ++d)
      X.columns[d].csv = referenceAxisName(d);
  x = field("x", vector, "current position");
  x.columns = csvOnly(defaultColumns<Dim>("x", vector));
  if (Dim > 1)  // x, y, z
    for (int d = 0; d < Dim; ++d)
      x.columns[d].csv = axisName(d);
  u = field("u", vector, "displacement");
  u.columns = csvOnly(defaultColumns<Dim>("u", vector));
  strain = field("strain", scalar, "1-D: engineering strain F - 1");
  strain.checkpoint = strain.migrate = false;
  if (Dim == 1)
    strain.columns = defaultColumns<Dim>("strain", scalar);
  stress = field("stress", tensor, "Cauchy stress (1-D: axial force per unit section)");
  stress.columns = defaultColumns<Dim>("stress", tensor);
  if (Dim == 2)  // symmetric: xx, yy, xy
    stress.columns = {stress.columns[0], stress.columns[3], stress.columns[1]};
  if (Dim == 3) {  // symmetric: xx, yy, zz, xy, yz, xz
    const auto& c = stress.columns;
    stress.columns = {c[0], c[4], c[8], c[1], c[5], c[2]};
  }
  stressZZ = field("stress_zz", scalar, "2-D: out-of-plane Cauchy stress (plane strain)");
  stressZZ.checkpoint = stressZZ.migrate = false;
  if (Dim == 2)
    stressZZ.columns = defaultColumns<Dim>("stress_zz", scalar);
  J = field("J", scalar, "2-D and 3-D: volume ratio det F");
  J.checkpoint = J.migrate = false;
  if (Dim > 1)
    J.columns = defaultColumns<Dim>("J", scalar);
  volume = field("volume", scalar, "current volume V_p (1-D: length)");
  volume.columns = defaultColumns<Dim>("volume", scalar);
  v = field("v", vector, "velocity");
  v.columns = defaultColumns<Dim>("v", vector);
  for (int d = 0; d < Dim; ++d)
    v.columns[d].exodus = std::string("velocity") + referenceAxisName(d);
  a = field("a", vector, "acceleration");
  a.columns = defaultColumns<Dim>("a", vector);
  for (int d = 0; d < Dim; ++d)
    a.columns[d].exodus = std::string("acceleration") + referenceAxisName(d);
  F = field("F", tensor, "2-D and 3-D: deformation gradient");
  if (Dim > 1)
    F.columns = defaultColumns<Dim>("F", tensor);
  mass = field("mass", scalar, "mass m_p");
  mass.columns = defaultColumns<Dim>("mass", scalar);
  section = field("section", scalar, "1-D: cross-section A(x_p)");
  if (Dim == 1)
    section.columns = defaultColumns<Dim>("section", scalar);
  body = field("body", scalar, "index of the body in the deck");
  body.columns = defaultColumns<Dim>("body", scalar);
  // Column k of the domain tensor is the half-vector r_k: r1_x, r1_y, r2_x, r2_y (2-D).
  domain = field("domain", tensor, "2-D and 3-D: the particle domain's half-vectors r1, r2 (r3)");
  domain0 = field("domain0", tensor, "2-D and 3-D: the reference half-vectors r01, r02 (r03)");
  if (Dim > 1)
    for (int k = 0; k < Dim; ++k)
      for (int c = 0; c < Dim; ++c) {
        const std::string axis = axisName(c);
        domain.columns.push_back({c * Dim + k, "r" + std::to_string(k + 1) + "_" + axis, ""});
        domain0.columns.push_back({c * Dim + k, "r0" + std::to_string(k + 1) + "_" + axis, ""});
      }
  material = field("material", scalar, "index of the material in the deck");
  force = field("force", vector, "external force on the particle");
  force.checkpoint = false;
  volume0 = field("volume0", scalar, "reference volume");
}

template <int Dim>
const BuiltinFields<Dim>& builtinFields() {
  static const BuiltinFields<Dim> fields;
  return fields;
}

template std::vector<OutputColumn> defaultColumns<1>(const std::string&, FieldShape);
template std::vector<OutputColumn> defaultColumns<2>(const std::string&, FieldShape);
template std::vector<OutputColumn> defaultColumns<3>(const std::string&, FieldShape);
template struct BuiltinFields<1>;
template struct BuiltinFields<2>;
template struct BuiltinFields<3>;
template const BuiltinFields<1>& builtinFields<1>();
template const BuiltinFields<2>& builtinFields<2>();
template const BuiltinFields<3>& builtinFields<3>();

}  // namespace impm
