// SPDX-License-Identifier: Zlib
#pragma once
// The one exception type btFracture throws. Messages name the problem, the offending value
// and where it came from (file, key, body), so that a user can act on them.
#include <stdexcept>
#include <string>

namespace btfracture {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace btfracture
