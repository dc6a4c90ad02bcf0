/* The arguments of one of our styles (fix, compute, command), read as
   LIGGGHTS' own styles read theirs (force->numeric, force->inumeric), with
   errors that name the style, the keyword, the bad value and what is
   allowed, e.g.
     Fix sequential/pack: porosity 1.5 must lie strictly between 0 and 1
     Compute primary/fabric: keyword 'prune' needs a value: once or iterate
   One reader for every style, so that they check alike and say alike. */

#ifndef LMP_STYLE_ARGS_H
#define LMP_STYLE_ARGS_H

#include <climits>
#include <initializer_list>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class Error;

class StyleArgs {
 public:
  // arg[0..narg): the style's arguments; `style` ("Fix sequential/pack")
  // begins every message; `keywords` are those the style takes.
  StyleArgs(Error *error, std::string style, int narg, char **arg,
            std::vector<std::string> keywords);

  int size() const { return narg_; }
  const char *operator[](int i) const { return arg_[i]; }
  bool is_keyword(const char *word) const;

  // Stops every rank: "<style>: message".
  [[noreturn]] void fail(const std::string &message) const;
  // arg[i] is no keyword of the style: names it and the allowed ones.
  [[noreturn]] void unknown_keyword(int i) const;

  // The value arg[i + 1] of keyword arg[i]; `what` says what it must be
  // when it is missing.
  const char *value(int i, const std::string &what) const;
  // ... as a finite number, as an integer, as yes or no (true: yes).
  double number(int i, const std::string &what) const;
  long integer(int i, const std::string &what) const;
  bool yes_no(int i) const;
  // ... an integer in lo..hi (hi LONG_MAX: at least lo); `note` says more
  // in the error, in parentheses.
  long integer_in(int i, long lo, long hi, const std::string &note = "") const;
  // ... one of `words`: its index.
  int choice(int i, std::initializer_list<const char *> words) const;
  // When !ok: "<keyword> <value> <rule>", e.g. "density -5 must be positive".
  void require(bool ok, int i, const std::string &rule) const;

  // Parsers of a word that is not the value of arg[i] (a second value):
  // `name` stands for it in the error.
  double number_of(const char *word, const std::string &name) const;
  long integer_of(const char *word, const std::string &name) const;

 private:
  Error *error_;
  std::string style_;
  int narg_;
  char **arg_;
  std::vector<std::string> keywords_;
};

}  // namespace LAMMPS_NS

#endif
