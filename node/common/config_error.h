#pragma once
// A bad input file of the node (its configuration, a host path): what() reads
// "FILE:LINE: KEY: expected ..., got ..."; the CLI exits with 2.
#include <stdexcept>

namespace skyig::services {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skyig::services
