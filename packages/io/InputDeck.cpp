#include "io/InputDeck.hpp"

#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "io/InputFile.hpp"

namespace impm {

namespace {

// Every int and double of the deck, and every entry of their arrays, must be a number from its
// first character to its last (core/Parameters.hpp, readNumber): Teuchos' XML reader takes
// the longest number at the start, "0.005xyz" as 0.005 and "1e" as 1.
void checkNumbers(const Teuchos::XMLObject& list, const std::string& path) {
  for (int k = 0; k < list.numChildren(); ++k) {
    const Teuchos::XMLObject& child = list.getChild(k);
    const std::string name = child.hasAttribute("name") ? child.getAttribute("name") : "";
    const std::string here = path.empty() ? name : path + "/" + name;
    if (child.getTag() == "ParameterList") {
      checkNumbers(child, here);
      continue;
    }
    if (child.getTag() != "Parameter" || !child.hasAttribute("type") ||
        !child.hasAttribute("value"))
      continue;
    const std::string type = child.getAttribute("type"), value = child.getAttribute("value");
    const bool array = type == "Array(int)" || type == "Array(double)";
    if (type != "int" && type != "double" && !array)
      continue;
    double number = 0.0;
    int integer = 0;
    std::vector<double> numbers;
    std::vector<int> integers;
    const bool read = type == "int"          ? readInteger(value, integer)
                      : type == "double"     ? readNumber(value, number)
                      : type == "Array(int)" ? readIntegers(value, integers)
                                             : readNumbers(value, numbers);
    if (!read)
      throw InputError(here, "cannot read '" + value + "' as " + type);
  }
}

// Deeper than this many ParameterLists, a deck is refused before Teuchos' reader recurses
// through it (10^4 levels overflowed the stack).  impm's decks are three or four levels deep;
// a Stratimikos or NOX list inside adds a few.
constexpr int kMaxDeckDepth = 32;

// The deepest nesting of <ParameterList> elements in the text (self-closed ones count as
// one level, comments are skipped).
int parameterListDepth(const std::string& xml) {
  int depth = 0, deepest = 0;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    if (xml.compare(at, 4, "<!--") == 0) {
      at = xml.find("-->", at);
      if (at == std::string::npos)
        break;
      continue;
    }
    if (xml.compare(at, 15, "</ParameterList") == 0) {
      --depth;
    } else if (xml.compare(at, 14, "<ParameterList") == 0) {
      const std::size_t end = xml.find('>', at);
      const bool closed = end != std::string::npos && end > at && xml[end - 1] == '/';
      deepest = std::max(deepest, depth + 1);
      if (!closed)
        ++depth;
    }
  }
  return deepest;
}

Teuchos::ParameterList readXml(const std::string& file) {
  if (const std::string why = notAnInputFile(file, "no such deck file"); !why.empty())
    throw InputError("", why);
  std::ifstream in(file);
  if (!in)
    throw InputError("", "cannot open the deck file");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  if (xml.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError("", "the deck file is empty");
  if (const int depth = parameterListDepth(xml); depth > kMaxDeckDepth)
    throw InputError("", "the deck nests " + std::to_string(depth) + " ParameterLists; at most " +
                             std::to_string(kMaxDeckDepth) +
                             " are read (a deck is a few levels deep)");
  Teuchos::ParameterList deck;
  try {
    deck = *Teuchos::getParametersFromXmlString(xml);
  } catch (const std::exception& e) {
    throw InputError("", "malformed XML deck: " + trilinosMessage(e.what()));
  }
  checkNumbers(Teuchos::StringInputSource(xml).getObject(), "");
  return deck;
}

// "it has: a, b" for the entries beside `path`'s last one in the deck ("it has none").
std::string namesBeside(const Teuchos::ParameterList& deck, const std::string& path) {
  const Teuchos::ParameterList* list = &deck;
  std::string rest = path;
  for (auto slash = rest.find('/'); slash != std::string::npos; slash = rest.find('/')) {
    if (!list->isSublist(rest.substr(0, slash)))
      return "it has none";
    list = &list->sublist(rest.substr(0, slash));
    rest = rest.substr(slash + 1);
  }
  std::string names;
  for (auto it = list->begin(); it != list->end(); ++it)
    if (list->isSublist(list->name(it)))
      names += (names.empty() ? "" : ", ") + list->name(it);
  return names.empty() ? "it has none" : "it has: " + names;
}

void applyOverride(Teuchos::ParameterList& deck, const Override& o,
                   const Teuchos::ParameterList& valid) {
  const std::string where = "--set " + o.path;
  Teuchos::ParameterEntry prototype, entry;
  if (insideOpaqueList(valid, deck, o.path))
    entry = parseByText(o.value);  // checked later by the list's owner (Stratimikos, NOX)
  else if (findValidEntry(valid, deck, o.path, prototype))
    entry = parseLike(prototype, o.value, o.path);
  else
    throw InputError(o.path, "unknown parameter (in " + where + ")");
  if (const auto created = newNamedEntry(valid, deck, o.path); !created.empty())
    throw InputError(o.path, "names no entry of the deck: " + created + " does not exist (" +
                                 namesBeside(deck, created) +
                                 "); a --set changes the deck's entries, it does not create "
                                 "them (in " +
                                 where + ")");
  Teuchos::ParameterList* list = &deck;
  std::string rest = o.path;
  for (auto slash = rest.find('/'); slash != std::string::npos; slash = rest.find('/')) {
    list = &list->sublist(rest.substr(0, slash));
    rest = rest.substr(slash + 1);
  }
  list->setEntry(rest, entry);
}

// A parameter named "... File" names a file relative to the deck's directory (so that a deck
// runs from any working directory); absolute names stay as they are.
void resolveFileNames(Teuchos::ParameterList& list, const std::string& directory) {
  const std::string suffix = " File";
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    Teuchos::ParameterEntry& entry = list.getEntry(name);
    if (entry.isList()) {
      resolveFileNames(Teuchos::getValue<Teuchos::ParameterList>(entry), directory);
    } else if (entry.isType<std::string>() && name.size() > suffix.size() &&
               name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const auto value = Teuchos::getValue<std::string>(entry);
      if (!value.empty() && value[0] != '/')
        entry.setValue(directory + "/" + value);
    }
  }
}

}  // namespace

Override parseOverride(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("", "--set expects Path/To/Param=value, got '" + text + "'");
  return Override{text.substr(0, eq), text.substr(eq + 1)};
}

Teuchos::ParameterList loadDeck(const std::string& file, const std::vector<Override>& overrides,
                                const Teuchos::ParameterList& valid) {
  Teuchos::ParameterList deck = readXml(file);
  for (const auto& o : overrides)
    applyOverride(deck, o, valid);
  validateParameters(deck, valid);
  const auto slash = file.find_last_of('/');
  resolveFileNames(deck, slash == std::string::npos ? "." : file.substr(0, slash));
  return deck;
}

std::string deckStem(const std::string& file) {
  std::string name =
      file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

}  // namespace impm
