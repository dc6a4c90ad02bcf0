#include "style_args.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "error.h"

using namespace LAMMPS_NS;

StyleArgs::StyleArgs(Error *error, std::string style, int narg, char **arg,
                     std::vector<std::string> keywords)
    : error_(error),
      style_(std::move(style)),
      narg_(narg),
      arg_(arg),
      keywords_(std::move(keywords)) {}

bool StyleArgs::is_keyword(const char *word) const {
  for (const std::string &k : keywords_)
    if (k == word) return true;
  return false;
}

void StyleArgs::fail(const std::string &message) const {
  error_->all(FLERR, (style_ + ": " + message).c_str());
  std::abort();  // Error::all does not return
}

void StyleArgs::unknown_keyword(int i) const {
  std::string allowed;
  for (const std::string &k : keywords_)
    allowed += (allowed.empty() ? "" : " ") + k;
  fail("unknown keyword '" + std::string(arg_[i]) + "': allowed are " +
       allowed);
}

const char *StyleArgs::value(int i, const std::string &what) const {
  if (i + 1 >= narg_)
    fail("keyword '" + std::string(arg_[i]) + "' needs a value: " + what);
  return arg_[i + 1];
}

double StyleArgs::number_of(const char *word, const std::string &name) const {
  char *end = nullptr;
  const double v = strtod(word, &end);
  if (end == word || *end != '\0' || !std::isfinite(v))
    fail(name + " '" + word + "' is not a number");
  return v;
}

long StyleArgs::integer_of(const char *word, const std::string &name) const {
  char *end = nullptr;
  const long v = strtol(word, &end, 10);
  if (end == word || *end != '\0')
    fail(name + " '" + word + "' is not an integer");
  return v;
}

double StyleArgs::number(int i, const std::string &what) const {
  return number_of(value(i, what), arg_[i]);
}

long StyleArgs::integer(int i, const std::string &what) const {
  return integer_of(value(i, what), arg_[i]);
}

long StyleArgs::integer_in(int i, long lo, long hi,
                           const std::string &note) const {
  const std::string range =
      hi == LONG_MAX ? "at least " + std::to_string(lo)
                     : std::to_string(lo) + ".." + std::to_string(hi);
  // a non-integer names the range too: "slices '2.5' is not an integer in
  // 1..1000"
  const char *word = value(i, "an integer " + range);
  char *end = nullptr;
  const long v = strtol(word, &end, 10);
  if (end == word || *end != '\0')
    fail(std::string(arg_[i]) + " '" + word + "' is not an integer " +
         (hi == LONG_MAX ? "(" + range + ")" : "in " + range));
  require(v >= lo && v <= hi, i,
          (hi == LONG_MAX ? "must be " : "must lie in ") + range +
              (note.empty() ? "" : " (" + note + ")"));
  return v;
}

bool StyleArgs::yes_no(int i) const {
  const char *v = value(i, "yes or no");
  if (strcmp(v, "yes") != 0 && strcmp(v, "no") != 0)
    fail(std::string(arg_[i]) + " '" + v + "' must be yes or no");
  return strcmp(v, "yes") == 0;
}

int StyleArgs::choice(int i, std::initializer_list<const char *> words) const {
  std::string allowed;
  size_t k = 0;
  for (const char *w : words)
    allowed += (k++ == 0 ? "" : k == words.size() ? " or " : ", ") +
               std::string(w);
  const char *v = value(i, allowed);
  int index = 0;
  for (const char *w : words) {
    if (strcmp(v, w) == 0) return index;
    ++index;
  }
  fail(std::string(arg_[i]) + " '" + v + "' is unknown: use " + allowed);
}

void StyleArgs::require(bool ok, int i, const std::string &rule) const {
  if (!ok) fail(std::string(arg_[i]) + " " + arg_[i + 1] + " " + rule);
}
