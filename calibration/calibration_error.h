#pragma once
// The one error a bad calibration file raises: its message names the file, where in it (XML
// line and element, PFM header or row) and the value that is wrong, so a configuration that
// points at it stops with exit 2 before anything renders.
#include <stdexcept>
#include <string>

namespace skyig::calibration {

class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skyig::calibration
