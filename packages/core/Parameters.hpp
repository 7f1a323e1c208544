#pragma once
// Input parameters: declaration, validation and documentation on Teuchos::ParameterList.
//
// Every component declares its parameters in a "valid list" (Peridigm's
// getValidParameters()): name, default, doc string and a validator.  The deck is then
// walked against the valid lists; the first problem stops the run with a one-line
// InputError naming the parameter's path.  Missing optional parameters get their defaults,
// so after validation every component reads its list without checks.
//
// Two conventions extend Teuchos' fixed lists:
//  - a valid sublist named "<name>" stands for any number of user sublists with free names
//    (Materials/<name>, Bodies/<name>, ...);
//  - a valid sublist named "[Key=value]" adds parameters that exist only when the user's
//    Key has that value (Materials/<name>/[Model=cubic] declares C).
// A valid sublist holding an entry named kOpaque is checked by its owner (Stratimikos and
// NOX lists), not by the walker.

#include <Teuchos_ParameterList.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace impm {

// Marker entry of opaque sublists; its doc string says who validates the list.
extern const char* const kOpaque;

// Base of impm's validators: check() throws InputError(path, "...") with a one-line reason,
// and may convert a value to the declared type (an int where a double is expected).
class Validator : public Teuchos::ParameterEntryValidator {
 public:
  explicit Validator(bool required = false) : required_(required) {}
  virtual void check(Teuchos::ParameterEntry& entry, const std::string& path) const = 0;
  // Short description of what is accepted, for --list-parameters.
  virtual std::string describe() const = 0;
  bool required() const { return required_; }

  const std::string getXMLTypeName() const override { return "impmValidator"; }
  void printDoc(const std::string& doc, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                const std::string& sublist) const override;

 private:
  bool required_;
};

// Bounds for a number; describe() prints them.
struct Bounds {
  double min = -1e300, max = 1e300;
  bool minOpen = false, maxOpen = false;
  static Bounds positive() { return {0.0, 1e300, true, false}; }
  static Bounds nonNegative() { return {0.0, 1e300, false, false}; }
  static Bounds atLeast(double v) { return {v, 1e300, false, false}; }
  static Bounds between(double a, double b) { return {a, b, false, false}; }
  static Bounds any() { return {}; }
  bool contains(double v) const;
  std::string describe() const;
};

// Declaration helpers: add a parameter with default, doc and validator to a valid list.
// Required parameters still carry a default: it fixes the type and is printed as an example.
void declareDouble(Teuchos::ParameterList& valid, const std::string& name, double value,
                   const std::string& doc, Bounds bounds = Bounds::any(), bool required = false);
void declareInt(Teuchos::ParameterList& valid, const std::string& name, int value,
                const std::string& doc, Bounds bounds = Bounds::any(), bool required = false);
void declareBool(Teuchos::ParameterList& valid, const std::string& name, bool value,
                 const std::string& doc);
void declareString(Teuchos::ParameterList& valid, const std::string& name, const std::string& value,
                   const std::string& doc, bool required = false);
void declareChoice(Teuchos::ParameterList& valid, const std::string& name, const std::string& value,
                   const std::vector<std::string>& choices, const std::string& doc,
                   bool required = false);
// A number or a muparser formula of `variables`.  Bounds apply to numbers; a formula is
// checked where it is evaluated.
void declareFormula(Teuchos::ParameterList& valid, const std::string& name,
                    const std::string& value, const std::vector<std::string>& variables,
                    const std::string& doc, Bounds bounds = Bounds::any(), bool required = false);
// Arrays: `sizes` lists the accepted lengths (empty: any length >= 1).
void declareIntArray(Teuchos::ParameterList& valid, const std::string& name,
                     const std::vector<int>& value, const std::vector<int>& sizes,
                     const std::string& doc, Bounds bounds = Bounds::any(), bool required = false);
void declareDoubleArray(Teuchos::ParameterList& valid, const std::string& name,
                        const std::vector<double>& value, const std::vector<int>& sizes,
                        const std::string& doc, Bounds bounds = Bounds::any(),
                        bool required = false);
// Names (Array(string)), any number of them.
void declareStringArray(Teuchos::ParameterList& valid, const std::string& name,
                        const std::vector<std::string>& value, const std::string& doc);
void declareOpaque(Teuchos::ParameterList& valid, const std::string& name, const std::string& doc);

// Reads a formula-or-number parameter as text.
std::string formulaText(const Teuchos::ParameterList& list, const std::string& name);

// Walks `user` against `valid`: throws InputError at the first unknown name (with a
// suggestion), wrong type, value out of range or missing required value; fills defaults.
void validateParameters(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& path = "");

// Whether the deck gave list's parameter `name` (false for a default validateParameters filled).
bool setInDeck(const Teuchos::ParameterList& list, const std::string& name);

// The valid entry that a user path refers to, resolving "<name>" and "[Key=value]" against
// the user's values; false when the path names no parameter.
bool findValidEntry(const Teuchos::ParameterList& valid, const Teuchos::ParameterList& user,
                    const std::string& path, Teuchos::ParameterEntry& found);

// The path of the named entry ("Materials/bar materail") that setting `path` would create
// because the user list has no entry of that name where the valid list takes any name ("<name>":
// a material, a body, a boundary condition); "" when it creates none.
std::string newNamedEntry(const Teuchos::ParameterList& valid, const Teuchos::ParameterList& user,
                          const std::string& path);

// True when `path` lies inside an opaque sublist (a Stratimikos or NOX list), whose entries
// have no declared type.
bool insideOpaqueList(const Teuchos::ParameterList& valid, const Teuchos::ParameterList& user,
                      const std::string& path);

// A deck's numbers are read whole or not at all: decimal, optionally signed, with an optional
// exponent, from the first character to the last (spaces around are allowed).  Not "0.5x",
// "1e", "0x10", "nan" or "inf", which C's readers take in part or as special values.
bool readNumber(const std::string& text, double& value);
bool readInteger(const std::string& text, int& value);
// "{a, b, ...}" (Teuchos' array syntax) read entry by entry as above; false if one is not.
bool readNumbers(const std::string& text, std::vector<double>& values);
bool readIntegers(const std::string& text, std::vector<int>& values);

// A value typed by its text alone: true/false a bool, an integer an int, a number a double,
// anything else a string.  For entries of opaque lists.
Teuchos::ParameterEntry parseByText(const std::string& text);

// Parses `text` into a value of the same type as `prototype` (Teuchos array syntax for
// arrays); throws InputError(path, ...) when it does not fit.
Teuchos::ParameterEntry parseLike(const Teuchos::ParameterEntry& prototype, const std::string& text,
                                  const std::string& path);

// " (did you mean 'x'?)" for the candidate closest to a misspelt name, or "".
std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates);

// Every parameter: path, type, default, accepted values and doc, one block each.
void listParameters(const Teuchos::ParameterList& valid, std::ostream& out,
                    const std::string& path = "");

// Name of an entry's type as written in XML decks: double, int, string, bool, Array(int), ...
std::string xmlTypeName(const Teuchos::ParameterEntry& entry);

}  // namespace impm
