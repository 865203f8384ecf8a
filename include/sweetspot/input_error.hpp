#pragma once
// The one exception type for bad user input: its message is a single line naming the file,
// the key (or CSV line), the value found and what was expected. The program prints it and exits 2.
#include <stdexcept>
#include <string>

namespace sweetspot {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sweetspot
