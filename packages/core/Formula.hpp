#pragma once
// A scalar field given in the deck either as a number or as a muparser expression of named
// variables (x, X, t, ...).  Evaluated on the host: formulas are read at set-up, once per
// step or once per Newton iteration, never inside device kernels.

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace impm {

class Formula {
 public:
  // Throws InputError("", message) when the expression does not parse or uses a name that
  // is not one of `variables` (the constants pi and e are always available).
  Formula(const std::string& expression, const std::vector<std::string>& variables);
  explicit Formula(double value = 0.0);

  // Values in the order of the variable names given at construction.
  double operator()(const std::vector<double>& values) const {
    return evaluate(values.data(), values.size());
  }
  template <std::size_t N>
  double operator()(const std::array<double, N>& values) const {
    return evaluate(values.data(), N);
  }
  double operator()(double v0) const { return evaluate(&v0, 1); }
  double operator()(double v0, double v1) const {
    const double v[2] = {v0, v1};
    return evaluate(v, 2);
  }
  double operator()(double v0, double v1, double v2) const {
    const double v[3] = {v0, v1, v2};
    return evaluate(v, 3);
  }

  bool isConstant() const { return !parser_; }
  // True when the expression does not use the named variable.
  bool independentOf(const std::string& variable) const;
  const std::string& expression() const { return expression_; }

 private:
  struct Parser;
  std::string allowedText() const;
  double evaluate(const double* values, std::size_t count) const;
  std::string expression_;
  double constant_ = 0.0;
  std::vector<std::string> variables_;
  std::shared_ptr<Parser> parser_;
};

}  // namespace impm
