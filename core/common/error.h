#pragma once
// Error types shared by every part. Library code reports errors by throwing
// these (or by return type), never by printing or exiting; the command line
// maps them to exit codes (InputError -> 2, everything else -> 1).
#include <stdexcept>
#include <string>

namespace rockface {

// Something went wrong that is not the user's input (I/O, a library failure).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input: names where (a file, a field path such as "joints[2].dip", or
// both) and why, so that one line on stderr tells the user what to fix.
class InputError : public Error {
 public:
  InputError(std::string where, std::string reason)
      : Error(where.empty() ? reason : where + ": " + reason),
        where_(std::move(where)),
        reason_(std::move(reason)) {}
  const std::string& where() const { return where_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string where_;
  std::string reason_;
};

// Long work was cancelled through the Progress interface.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace rockface
