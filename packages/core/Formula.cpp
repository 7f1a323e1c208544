#include "core/Formula.hpp"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/Errors.hpp"

namespace impm {

struct Formula::Parser {
  mu::Parser parser;
  std::vector<double> values;  // muparser binds variables by address: storage must not move
  std::vector<std::string> used;
};

namespace {

bool parseNumber(const std::string& text, double& value) {
  const char* begin = text.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if (end == begin)
    return false;
  while (*end == ' ' || *end == '\t')
    ++end;
  return *end == '\0';
}

}  // namespace

std::string Formula::allowedText() const {
  std::string allowed;
  for (const auto& v : variables_)
    allowed += (allowed.empty() ? "" : ", ") + v;
  return allowed.empty() ? "none" : allowed;
}

Formula::Formula(double value) : expression_(std::to_string(value)), constant_(value) {}

Formula::Formula(const std::string& expression, const std::vector<std::string>& variables)
    : expression_(expression), variables_(variables) {
  if (parseNumber(expression, constant_))
    return;
  auto p = std::make_shared<Parser>();
  p->values.assign(variables.size(), 0.0);
  try {
    p->parser.DefineConst("pi", M_PI);
    p->parser.DefineConst("e", M_E);
    for (std::size_t k = 0; k < variables.size(); ++k)
      p->parser.DefineVar(variables[k], &p->values[k]);
    p->parser.SetExpr(expression);
    // GetUsedVar parses the expression and lists every name it uses, defined or not.
    for (const auto& used : p->parser.GetUsedVar())
      p->used.push_back(used.first);
  } catch (mu::Parser::exception_type& e) {
    throw InputError("", "cannot read formula '" + expression + "': " + e.GetMsg() +
                             " (variables allowed here: " + allowedText() + ")");
  }
  for (const auto& used : p->used)
    if (std::find(variables.begin(), variables.end(), used) == variables.end())
      throw InputError("", "formula '" + expression + "' uses '" + used +
                               "', which is not a variable here (allowed: " + allowedText() + ")");
  parser_ = p;
}

double Formula::evaluate(const double* values, std::size_t count) const {
  if (!parser_)
    return constant_;
  for (std::size_t k = 0; k < parser_->values.size() && k < count; ++k)
    parser_->values[k] = values[k];
  try {
    return parser_->parser.Eval();
  } catch (mu::Parser::exception_type& e) {
    throw InputError("", "cannot evaluate formula '" + expression_ + "': " + e.GetMsg());
  }
}

bool Formula::independentOf(const std::string& variable) const {
  if (!parser_)
    return true;
  for (const auto& used : parser_->used)
    if (used == variable)
      return false;
  return true;
}

}  // namespace impm
