#pragma once
// One exception type for everything a user can get wrong (house style: Drake's
// DRAKE_THROW_UNLESS). The message names the file, the field and the offending value;
// `main` catches it, prints the one line and exits with status 2.
#include <stdexcept>
#include <string>

namespace touchdown {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// A fit's solver failed on input that was valid (its cost could not be evaluated). `main` prints
// the one line and exits with status 3, as for integ::IntegrationFailure (lander/integ keeps its
// own type: it uses no other module); the message says what failed and why.
class SolverFailure : public std::runtime_error {
 public:
  explicit SolverFailure(const std::string& message) : std::runtime_error(message) {}
};

// "file: field: message (value)" - the single shape every input error takes.
inline InputError MakeInputError(const std::string& file, const std::string& field,
                                 const std::string& message) {
  std::string text = file.empty() ? std::string() : file + ": ";
  if (!field.empty()) text += field + ": ";
  return InputError(text + message);
}

}  // namespace touchdown
