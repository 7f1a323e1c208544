#include "core/Parameters.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <regex>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Formula.hpp"

namespace impm {

const char* const kOpaque = ".validated-by";

namespace {

using Teuchos::Array;
using Teuchos::ParameterEntry;
using Teuchos::ParameterList;

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k)
    out += (k ? sep : "") + items[k];
  return out;
}

std::string childPath(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "/" + name;
}

// A value as a user would write it: {0, 1.5} for arrays, true/false for bools.
std::string shortValue(const ParameterEntry& entry) {
  std::ostringstream s;
  s << std::setprecision(10);
  if (entry.isType<bool>()) {
    s << (Teuchos::getValue<bool>(entry) ? "true" : "false");
  } else if (entry.isType<Array<double>>() || entry.isType<Array<int>>()) {
    s << "{";
    if (entry.isType<Array<double>>()) {
      const auto& a = Teuchos::getValue<Array<double>>(entry);
      for (decltype(a.size()) k = 0; k < a.size(); ++k)
        s << (k ? ", " : "") << a[k];
    } else {
      const auto& a = Teuchos::getValue<Array<int>>(entry);
      for (decltype(a.size()) k = 0; k < a.size(); ++k)
        s << (k ? ", " : "") << a[k];
    }
    s << "}";
  } else if (entry.isType<Array<std::string>>()) {
    s << "{"
      << join(std::vector<std::string>(Teuchos::getValue<Array<std::string>>(entry).begin(),
                                       Teuchos::getValue<Array<std::string>>(entry).end()),
              ", ")
      << "}";
  } else if (entry.isType<std::string>() && Teuchos::getValue<std::string>(entry).empty()) {
    s << "\"\"";
  } else {
    entry.leftshift(s, false);
  }
  std::string v = s.str();
  return v.size() > 60 ? v.substr(0, 57) + "..." : v;
}

// Accepts a double, or an int that is converted to a double.
bool readDouble(ParameterEntry& entry, double& value) {
  if (entry.isType<double>()) {
    value = Teuchos::getValue<double>(entry);
    return true;
  }
  if (entry.isType<int>()) {
    value = Teuchos::getValue<int>(entry);
    entry.setValue(value, entry.isDefault(), entry.docString(), entry.validator());
    return true;
  }
  return false;
}

class NumberValidator : public Validator {
 public:
  NumberValidator(bool integer, Bounds bounds, bool required)
      : Validator(required), integer_(integer), bounds_(bounds) {}
  void check(ParameterEntry& entry, const std::string& path) const override {
    double value = 0;
    if (integer_) {
      if (!entry.isType<int>())
        throw InputError(path, "expected type int, got " + xmlTypeName(entry));
      value = Teuchos::getValue<int>(entry);
    } else if (!readDouble(entry, value)) {
      throw InputError(path, "expected type double, got " + xmlTypeName(entry));
    }
    if (!std::isfinite(value) || !bounds_.contains(value))
      throw InputError(path, "must be " + bounds_.describe() + " (got " + shortValue(entry) + ")");
  }
  std::string describe() const override {
    return std::string(integer_ ? "int" : "double") + ", " + bounds_.describe();
  }

 private:
  bool integer_;
  Bounds bounds_;
};

class StringValidator : public Validator {
 public:
  StringValidator(std::vector<std::string> choices, bool required)
      : Validator(required), choices_(std::move(choices)) {}
  void check(ParameterEntry& entry, const std::string& path) const override {
    if (!entry.isType<std::string>())
      throw InputError(path, "expected type string, got " + xmlTypeName(entry));
    const auto& value = Teuchos::getValue<std::string>(entry);
    if (!choices_.empty() && std::find(choices_.begin(), choices_.end(), value) == choices_.end())
      throw InputError(path, "must be one of: " + join(choices_, ", ") + " (got '" + value + "')");
    if (choices_.empty() && required() && value.empty())
      throw InputError(path, "must not be empty");
  }
  std::string describe() const override {
    return choices_.empty() ? "string" : "one of: " + join(choices_, ", ");
  }

 private:
  std::vector<std::string> choices_;
};

class FormulaValidator : public Validator {
 public:
  FormulaValidator(std::vector<std::string> variables, Bounds bounds, bool required)
      : Validator(required), variables_(std::move(variables)), bounds_(bounds) {}
  void check(ParameterEntry& entry, const std::string& path) const override {
    double value = 0;
    if (readDouble(entry, value)) {
      if (!std::isfinite(value) || !bounds_.contains(value))
        throw InputError(path,
                         "must be " + bounds_.describe() + " (got " + shortValue(entry) + ")");
      return;
    }
    if (!entry.isType<std::string>())
      throw InputError(path, "expected a number or a formula (string), got " + xmlTypeName(entry));
    try {
      const Formula f(Teuchos::getValue<std::string>(entry), variables_);
      if (f.isConstant() && !bounds_.contains(f({})))
        throw InputError(path,
                         "must be " + bounds_.describe() + " (got " + shortValue(entry) + ")");
    } catch (const InputError& e) {
      if (!e.path().empty())
        throw;
      throw InputError(path, e.what());
    }
  }
  std::string describe() const override {
    std::string out = "number or formula";
    out += variables_.empty() ? "" : " of " + join(variables_, ", ");
    if (bounds_.min > -1e300 || bounds_.max < 1e300)
      out += "; value " + bounds_.describe();
    return out;
  }

 private:
  std::vector<std::string> variables_;
  Bounds bounds_;
};

template <class T>
class ArrayValidator : public Validator {
 public:
  ArrayValidator(std::vector<int> sizes, Bounds bounds, bool required)
      : Validator(required), sizes_(std::move(sizes)), bounds_(bounds) {}
  void check(ParameterEntry& entry, const std::string& path) const override {
    const bool isInt = std::is_same<T, int>::value;
    if (!entry.isType<Array<T>>()) {
      // An Array(int) where Array(double) is expected is converted.
      if (!isInt && entry.isType<Array<int>>()) {
        const auto& ints = Teuchos::getValue<Array<int>>(entry);
        Array<T> converted(ints.begin(), ints.end());
        entry.setValue(converted, entry.isDefault(), entry.docString(), entry.validator());
      } else {
        throw InputError(path, std::string("expected type ") +
                                   (isInt ? "Array(int)" : "Array(double)") + ", got " +
                                   xmlTypeName(entry));
      }
    }
    const auto& values = Teuchos::getValue<Array<T>>(entry);
    const int n = static_cast<int>(values.size());
    if (sizes_.empty() ? n < 1 : std::find(sizes_.begin(), sizes_.end(), n) == sizes_.end())
      throw InputError(path, "expected " + sizeText() + ", got " + std::to_string(n));
    for (const T& v : values)
      if (!std::isfinite(double(v)) || !bounds_.contains(double(v)))
        throw InputError(
            path, "every entry must be " + bounds_.describe() + " (got " + shortValue(entry) + ")");
  }
  std::string describe() const override {
    std::string out = std::string(std::is_same<T, int>::value ? "Array(int)" : "Array(double)") +
                      " of " + sizeText();
    if (bounds_.min > -1e300 || bounds_.max < 1e300)
      out += ", each " + bounds_.describe();
    return out;
  }

 private:
  std::string sizeText() const {
    if (sizes_.empty())
      return "1 or more entries";
    std::vector<std::string> s;
    for (int k : sizes_)
      s.push_back(std::to_string(k));
    return join(s, " or ") + (sizes_.size() == 1 && sizes_[0] == 1 ? " entry" : " entries");
  }
  std::vector<int> sizes_;
  Bounds bounds_;
};

// Names: Array(string) of any length (empty included), entries trimmed of blanks.
class StringArrayValidator : public Validator {
 public:
  void check(ParameterEntry& entry, const std::string& path) const override {
    if (!entry.isType<Array<std::string>>())
      throw InputError(path, "expected type Array(string), got " + xmlTypeName(entry));
    Array<std::string> values = Teuchos::getValue<Array<std::string>>(entry);
    for (auto& v : values) {
      const auto first = v.find_first_not_of(" \t"), last = v.find_last_not_of(" \t");
      v = first == std::string::npos ? "" : v.substr(first, last - first + 1);
      if (v.empty())
        throw InputError(path, "an entry is empty");
    }
    entry.setValue(values, entry.isDefault(), entry.docString(), entry.validator());
  }
  std::string describe() const override { return "Array(string), any length"; }
};

class BoolValidator : public Validator {
 public:
  void check(ParameterEntry& entry, const std::string& path) const override {
    if (!entry.isType<bool>())
      throw InputError(path, "expected type bool, got " + xmlTypeName(entry));
  }
  std::string describe() const override { return "bool"; }
};

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

bool isTemplate(const std::string& name) {
  return name == "<name>";
}
bool isVariant(const std::string& name) {
  return name.size() > 2 && name.front() == '[';
}

// The valid entries that apply to `user`: the common ones plus the variants selected by the
// user's discriminating values.  Variant keys are validated before they are used.
ParameterList effectiveValidList(ParameterList& user, const ParameterList& valid,
                                 const std::string& path) {
  ParameterList effective(valid.name());
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (!isVariant(name))
      effective.setEntry(name, valid.entry(it));
  }
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (!isVariant(name))
      continue;
    const auto eq = name.find('=');
    const std::string key = name.substr(1, eq - 1);
    const std::string value = name.substr(eq + 1, name.size() - eq - 2);
    if (!user.isParameter(key) && valid.isParameter(key))
      user.setEntry(key, valid.getEntry(key));
    if (!user.isParameter(key))
      continue;
    auto keyValidator = Teuchos::rcp_dynamic_cast<const Validator>(valid.getEntry(key).validator());
    if (keyValidator)
      keyValidator->check(user.getEntry(key), childPath(path, key));
    if (!user.isType<std::string>(key) || user.get<std::string>(key) != value)
      continue;
    const ParameterList& variant = valid.sublist(name);
    for (auto v = variant.begin(); v != variant.end(); ++v)
      effective.setEntry(variant.name(v), variant.entry(v));
  }
  return effective;
}

}  // namespace

std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bestDistance = 4;
  for (const auto& candidate : candidates) {
    const std::size_t d = editDistance(name, candidate);
    if (d < bestDistance && d < std::max<std::size_t>(candidate.size(), 2)) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

namespace {

std::string suggestion(const std::string& name, const ParameterList& valid) {
  std::vector<std::string> candidates;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& candidate = valid.name(it);
    if (!isTemplate(candidate) && !isVariant(candidate) && candidate != kOpaque)
      candidates.push_back(candidate);
  }
  return didYouMean(name, candidates);
}

bool isOpaque(const ParameterList& valid) {
  return valid.isParameter(kOpaque);
}

void checkEntry(ParameterEntry& entry, const ParameterEntry& validEntry, const std::string& path) {
  auto validator = Teuchos::rcp_dynamic_cast<const Validator>(validEntry.validator());
  if (validator) {
    validator->check(entry, path);
  } else if (entry.getAny().type() != validEntry.getAny().type()) {
    throw InputError(path,
                     "expected type " + xmlTypeName(validEntry) + ", got " + xmlTypeName(entry));
  }
}

bool isRequired(const ParameterEntry& entry) {
  auto validator = Teuchos::rcp_dynamic_cast<const Validator>(entry.validator());
  return validator && validator->required();
}

}  // namespace

// ---------------------------------------------------------------------------------------

void Validator::printDoc(const std::string& doc, std::ostream& out) const {
  out << doc << " [" << describe() << "]\n";
}

// Teuchos calls this when a default is set with its validator; impm's own walk calls
// check() instead, so that a required parameter may carry a placeholder default.
void Validator::validate(const ParameterEntry& /*entry*/, const std::string& /*name*/,
                         const std::string& /*sublist*/) const {}

bool Bounds::contains(double v) const {
  const bool aboveMin = minOpen ? v > min : v >= min;
  const bool belowMax = maxOpen ? v < max : v <= max;
  return aboveMin && belowMax;
}

std::string Bounds::describe() const {
  std::ostringstream s;
  s << std::setprecision(10);
  const bool hasMin = min > -1e300, hasMax = max < 1e300;
  if (hasMin && hasMax)
    s << "in " << (minOpen ? "(" : "[") << min << ", " << max << (maxOpen ? ")" : "]");
  else if (hasMin)
    s << (minOpen ? "> " : ">= ") << min;
  else if (hasMax)
    s << (maxOpen ? "< " : "<= ") << max;
  else
    s << "any value";
  return s.str();
}

void declareDouble(ParameterList& valid, const std::string& name, double value,
                   const std::string& doc, Bounds bounds, bool required) {
  valid.set(name, value, doc, Teuchos::rcp(new NumberValidator(false, bounds, required)));
}

void declareInt(ParameterList& valid, const std::string& name, int value, const std::string& doc,
                Bounds bounds, bool required) {
  valid.set(name, value, doc, Teuchos::rcp(new NumberValidator(true, bounds, required)));
}

void declareBool(ParameterList& valid, const std::string& name, bool value,
                 const std::string& doc) {
  valid.set(name, value, doc, Teuchos::rcp(new BoolValidator()));
}

void declareString(ParameterList& valid, const std::string& name, const std::string& value,
                   const std::string& doc, bool required) {
  valid.set(name, value, doc, Teuchos::rcp(new StringValidator({}, required)));
}

void declareChoice(ParameterList& valid, const std::string& name, const std::string& value,
                   const std::vector<std::string>& choices, const std::string& doc, bool required) {
  valid.set(name, value, doc, Teuchos::rcp(new StringValidator(choices, required)));
}

void declareFormula(ParameterList& valid, const std::string& name, const std::string& value,
                    const std::vector<std::string>& variables, const std::string& doc,
                    Bounds bounds, bool required) {
  valid.set(name, value, doc, Teuchos::rcp(new FormulaValidator(variables, bounds, required)));
}

void declareIntArray(ParameterList& valid, const std::string& name, const std::vector<int>& value,
                     const std::vector<int>& sizes, const std::string& doc, Bounds bounds,
                     bool required) {
  valid.set(name, Array<int>(value.begin(), value.end()), doc,
            Teuchos::rcp(new ArrayValidator<int>(sizes, bounds, required)));
}

void declareStringArray(ParameterList& valid, const std::string& name,
                        const std::vector<std::string>& value, const std::string& doc) {
  valid.set(name, Array<std::string>(value.begin(), value.end()), doc,
            Teuchos::rcp(new StringArrayValidator()));
}

void declareDoubleArray(ParameterList& valid, const std::string& name,
                        const std::vector<double>& value, const std::vector<int>& sizes,
                        const std::string& doc, Bounds bounds, bool required) {
  valid.set(name, Array<double>(value.begin(), value.end()), doc,
            Teuchos::rcp(new ArrayValidator<double>(sizes, bounds, required)));
}

void declareOpaque(ParameterList& valid, const std::string& name, const std::string& doc) {
  valid.sublist(name, false, doc).set(kOpaque, std::string(), doc);
}

std::string formulaText(const ParameterList& list, const std::string& name) {
  const ParameterEntry& entry = list.getEntry(name);
  if (entry.isType<std::string>())
    return Teuchos::getValue<std::string>(entry);
  std::ostringstream s;
  s << std::setprecision(17)
    << (entry.isType<int>() ? double(Teuchos::getValue<int>(entry))
                            : Teuchos::getValue<double>(entry));
  return s.str();
}

void validateParameters(ParameterList& user, const ParameterList& valid, const std::string& path) {
  if (isOpaque(valid))
    return;
  const ParameterList effective = effectiveValidList(user, valid, path);
  const bool hasTemplate = effective.isSublist("<name>");

  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string& name = user.name(it);
    const std::string here = childPath(path, name);
    ParameterEntry& entry = user.getEntry(name);
    if (effective.isParameter(name) && !isTemplate(name)) {
      const ParameterEntry& validEntry = effective.getEntry(name);
      if (validEntry.isList() != entry.isList())
        throw InputError(here, validEntry.isList() ? "must be a ParameterList"
                                                   : "must be a parameter, not a ParameterList");
      if (entry.isList())
        validateParameters(user.sublist(name), effective.sublist(name), here);
      else
        checkEntry(entry, validEntry, here);
    } else if (hasTemplate && entry.isList()) {
      validateParameters(user.sublist(name), effective.sublist("<name>"), here);
    } else {
      throw InputError(here, "unknown parameter" + suggestion(name, effective));
    }
  }

  for (auto it = effective.begin(); it != effective.end(); ++it) {
    const std::string& name = effective.name(it);
    if (isTemplate(name) || name == kOpaque || user.isParameter(name))
      continue;
    const ParameterEntry& validEntry = effective.entry(it);
    if (validEntry.isList()) {
      validateParameters(user.sublist(name), effective.sublist(name), childPath(path, name));
    } else if (isRequired(validEntry)) {
      throw InputError(childPath(path, name), "required parameter is missing");
    } else {
      // Marked as a default, so that setInDeck tells it from a value the deck gave.
      ParameterEntry filled = validEntry;
      filled.setAnyValue(validEntry.getAny(false), true);
      user.setEntry(name, filled);
    }
  }
}

bool setInDeck(const ParameterList& list, const std::string& name) {
  const ParameterEntry* entry = list.getEntryPtr(name);
  return entry && !entry->isDefault();
}

bool findValidEntry(const ParameterList& valid, const ParameterList& user, const std::string& path,
                    ParameterEntry& found) {
  if (isOpaque(valid))
    return false;
  const auto slash = path.find('/');
  const std::string head = path.substr(0, slash);
  ParameterList userCopy(user);
  const ParameterList effective = effectiveValidList(userCopy, valid, "");
  const ParameterEntry* entry = effective.getEntryPtr(head);
  if (!entry && slash != std::string::npos && effective.isSublist("<name>"))
    entry = effective.getEntryPtr("<name>");
  if (!entry)
    return false;
  if (slash == std::string::npos) {
    if (entry->isList())
      return false;
    found = *entry;
    return true;
  }
  if (!entry->isList())
    return false;
  const ParameterList& validSub = Teuchos::getValue<ParameterList>(*entry);
  const ParameterList userSub = user.isSublist(head) ? user.sublist(head) : ParameterList();
  return findValidEntry(validSub, userSub, path.substr(slash + 1), found);
}

std::string newNamedEntry(const ParameterList& valid, const ParameterList& user,
                          const std::string& path) {
  if (isOpaque(valid))
    return "";
  const auto slash = path.find('/');
  if (slash == std::string::npos)
    return "";
  const std::string head = path.substr(0, slash);
  ParameterList userCopy(user);
  const ParameterList effective = effectiveValidList(userCopy, valid, "");
  const ParameterEntry* entry = effective.getEntryPtr(head);
  if (!entry && effective.isSublist("<name>")) {
    if (!user.isSublist(head))
      return head;
    entry = effective.getEntryPtr("<name>");
  }
  if (!entry || !entry->isList())
    return "";
  const ParameterList userSub = user.isSublist(head) ? user.sublist(head) : ParameterList();
  const auto below =
      newNamedEntry(Teuchos::getValue<ParameterList>(*entry), userSub, path.substr(slash + 1));
  return below.empty() ? "" : head + "/" + below;
}

bool insideOpaqueList(const ParameterList& valid, const ParameterList& user,
                      const std::string& path) {
  if (isOpaque(valid))
    return true;
  const auto slash = path.find('/');
  if (slash == std::string::npos)
    return false;
  const std::string head = path.substr(0, slash);
  ParameterList userCopy(user);
  const ParameterList effective = effectiveValidList(userCopy, valid, "");
  const ParameterEntry* entry = effective.getEntryPtr(head);
  if (!entry && effective.isSublist("<name>"))
    entry = effective.getEntryPtr("<name>");
  if (!entry || !entry->isList())
    return false;
  const ParameterList userSub = user.isSublist(head) ? user.sublist(head) : ParameterList();
  return insideOpaqueList(Teuchos::getValue<ParameterList>(*entry), userSub,
                          path.substr(slash + 1));
}

namespace {

// The text without the spaces around it.
std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

bool decimal(const std::string& t) {
  static const std::regex pattern(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
  return std::regex_match(t, pattern);
}

// The entries of "{a, b, ...}", or false when the braces are missing.
bool arrayEntries(const std::string& text, std::vector<std::string>& entries) {
  const std::string t = trimmed(text);
  if (t.size() < 2 || t.front() != '{' || t.back() != '}')
    return false;
  entries.clear();
  const std::string inside = t.substr(1, t.size() - 2);
  if (trimmed(inside).empty())
    return true;
  std::stringstream items(inside);
  for (std::string item; std::getline(items, item, ',');)
    entries.push_back(item);
  if (inside.back() == ',')
    entries.push_back("");  // "{1,}" has an empty last entry
  return true;
}

}  // namespace

bool readNumber(const std::string& text, double& value) {
  const std::string t = trimmed(text);
  if (!decimal(t))
    return false;
  value = std::strtod(t.c_str(), nullptr);
  return std::isfinite(value);  // 1e999 overflows
}

bool readInteger(const std::string& text, int& value) {
  const std::string t = trimmed(text);
  static const std::regex pattern(R"([+-]?\d+)");
  if (!std::regex_match(t, pattern))
    return false;
  errno = 0;
  const long v = std::strtol(t.c_str(), nullptr, 10);
  if (errno == ERANGE || v < INT_MIN || v > INT_MAX)
    return false;
  value = static_cast<int>(v);
  return true;
}

namespace {

// "{a, b, ...}" entry by entry with `readOne`.
template <class T, class Read>
bool readArray(const std::string& text, std::vector<T>& values, Read readOne) {
  std::vector<std::string> entries;
  if (!arrayEntries(text, entries))
    return false;
  values.resize(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k)
    if (!readOne(entries[k], values[k]))
      return false;
  return true;
}

}  // namespace

bool readNumbers(const std::string& text, std::vector<double>& values) {
  return readArray(text, values, [](const std::string& t, double& v) { return readNumber(t, v); });
}

bool readIntegers(const std::string& text, std::vector<int>& values) {
  return readArray(text, values, [](const std::string& t, int& v) { return readInteger(t, v); });
}

ParameterEntry parseByText(const std::string& text) {
  ParameterEntry entry;
  char* end = nullptr;
  const long integer = std::strtol(text.c_str(), &end, 10);
  if (!text.empty() && *end == '\0' && integer >= INT_MIN && integer <= INT_MAX) {
    entry.setValue(static_cast<int>(integer));
    return entry;
  }
  const double number = std::strtod(text.c_str(), &end);
  if (!text.empty() && *end == '\0')
    entry.setValue(number);
  else if (text == "true" || text == "false")
    entry.setValue(text == "true");
  else
    entry.setValue(text);
  return entry;
}

ParameterEntry parseLike(const ParameterEntry& prototype, const std::string& text,
                         const std::string& path) {
  ParameterEntry entry;
  auto fail = [&](const std::string& type) -> ParameterEntry {
    throw InputError(path, "cannot read '" + text + "' as " + type);
  };
  try {
    if (prototype.isType<int>()) {
      int v = 0;
      if (!readInteger(text, v))
        return fail("int");
      entry.setValue(v);
    } else if (prototype.isType<double>()) {
      double v = 0.0;
      if (!readNumber(text, v))
        return fail("double");
      entry.setValue(v);
    } else if (prototype.isType<bool>()) {
      if (text == "true" || text == "1")
        entry.setValue(true);
      else if (text == "false" || text == "0")
        entry.setValue(false);
      else
        return fail("bool");
    } else if (prototype.isType<Array<int>>()) {
      std::vector<int> v;
      if (!readIntegers(text, v))
        return fail("Array(int)");
      entry.setValue(Array<int>(v.begin(), v.end()));
    } else if (prototype.isType<Array<double>>()) {
      std::vector<double> v;
      if (!readNumbers(text, v))
        return fail("Array(double)");
      entry.setValue(Array<double>(v.begin(), v.end()));
    } else if (prototype.isType<Array<std::string>>()) {
      entry.setValue(Teuchos::fromStringToArray<std::string>(text));
    } else {
      // Strings, and number-or-formula parameters: a number stays a number.
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      const auto validator =
          Teuchos::rcp_dynamic_cast<const FormulaValidator>(prototype.validator());
      if (validator && !text.empty() && *end == '\0')
        entry.setValue(v);
      else
        entry.setValue(text);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    return fail(xmlTypeName(prototype));
  }
  return entry;
}

namespace {

// `condition`: "Model = cubic" for the parameters of a variant list, else empty.
void listEntries(const ParameterList& valid, std::ostream& out, const std::string& path,
                 const std::string& condition) {
  if (isOpaque(valid)) {
    out << path << "/...\n    " << valid.getEntry(kOpaque).docString() << "\n\n";
    return;
  }
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    const ParameterEntry& entry = valid.entry(it);
    if (entry.isList())
      continue;
    auto validator = Teuchos::rcp_dynamic_cast<const Validator>(entry.validator());
    const bool formula =
        Teuchos::rcp_dynamic_cast<const FormulaValidator>(validator) != Teuchos::null;
    out << childPath(path, name) << "  (" << (formula ? "double or string" : xmlTypeName(entry))
        << ", " << (isRequired(entry) ? "required, e.g. " : "default ") << shortValue(entry)
        << (condition.empty() ? "" : "; only when " + condition) << ")\n";
    out << "    " << entry.docString();
    if (validator)
      out << " [" << validator->describe() << "]";
    out << "\n\n";
  }
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (!valid.entry(it).isList())
      continue;
    if (isVariant(name)) {
      std::string c = name.substr(1, name.size() - 2);
      c.replace(c.find('='), 1, " = ");
      listEntries(valid.sublist(name), out, path, c);
    } else {
      listEntries(valid.sublist(name), out, childPath(path, name), condition);
    }
  }
}

}  // namespace

void listParameters(const ParameterList& valid, std::ostream& out, const std::string& path) {
  listEntries(valid, out, path, "");
}

std::string xmlTypeName(const ParameterEntry& entry) {
  if (entry.isList())
    return "ParameterList";
  if (entry.isType<double>())
    return "double";
  if (entry.isType<int>())
    return "int";
  if (entry.isType<bool>())
    return "bool";
  if (entry.isType<std::string>())
    return "string";
  if (entry.isType<Array<int>>())
    return "Array(int)";
  if (entry.isType<Array<double>>())
    return "Array(double)";
  if (entry.isType<Array<std::string>>())
    return "Array(string)";
  if (entry.isType<long long>())
    return "long long";
  return entry.getAny().typeName();
}

}  // namespace impm
