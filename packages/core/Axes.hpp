#pragma once
// The names decks and outputs give to directions, in every dimension: components x, y, z;
// reference coordinates X, Y, Z; the variables of a formula.  One list, so that a name
// cannot differ between the parameters that read it and the outputs that write it.

#include <array>
#include <string>
#include <vector>

namespace impm {

// "x", "y", "z" for d = 0, 1, 2.
inline const char* axisName(int d) {
  static const char* const names[3] = {"x", "y", "z"};
  return names[d];
}

// "X", "Y", "Z": reference coordinates.
inline const char* referenceAxisName(int d) {
  static const char* const names[3] = {"X", "Y", "Z"};
  return names[d];
}

// The first Dim component names.
template <int Dim>
std::vector<std::string> axisNames() {
  std::vector<std::string> names;
  for (int d = 0; d < Dim; ++d)
    names.push_back(axisName(d));
  return names;
}

// The variables of a body's formulas in a Dim-D deck: current position, reference position,
// time (x, y, z, X, Y, Z, t in 3-D).
template <int Dim>
std::vector<std::string> positionTimeVariables() {
  auto names = axisNames<Dim>();
  for (int d = 0; d < Dim; ++d)
    names.push_back(referenceAxisName(d));
  names.push_back("t");
  return names;
}

// Their values, in that order.
template <int Dim>
std::array<double, 2 * Dim + 1> positionTimeArguments(const double* x, const double* X, double t) {
  std::array<double, 2 * Dim + 1> a{};
  for (int d = 0; d < Dim; ++d)
    a[d] = x[d], a[Dim + d] = X[d];
  a[2 * Dim] = t;
  return a;
}

// The variables of a boundary value in a Dim-D deck: position and time (x, y, z, t).
template <int Dim>
std::vector<std::string> pointTimeVariables() {
  auto names = axisNames<Dim>();
  names.push_back("t");
  return names;
}

// Every name a formula may use in some dimension, for the validators, which see a deck
// before its dimension is known; reading a formula checks it against its own dimension's.
inline std::vector<std::string> anyPositionTimeVariables() {
  return positionTimeVariables<3>();
}
inline std::vector<std::string> anyPointTimeVariables() {
  return pointTimeVariables<3>();
}

}  // namespace impm
