// SPDX-License-Identifier: Zlib
#pragma once
// Locale-independent tokenizing and number parsing for the text mesh formats.
#include <string_view>
#include <vector>

namespace btfracture {

// Splits a line at spaces, tabs and carriage returns.
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens);

// Whole-token parses; false when the token is not exactly one number ("nan" and "inf" are numbers).
bool parseDouble(std::string_view token, double& value);
bool parseInteger(std::string_view token, long long& value);

// Reads a text file line by line: next() yields each line without its end-of-line characters.
class LineReader {
public:
    explicit LineReader(std::string_view text) : text_(text) {}
    bool next(std::string_view& line);
    int lineNumber() const { return lineNumber_; }  // 1-based number of the last line returned
    size_t offset() const { return position_; }     // byte offset just after the last line

private:
    std::string_view text_;
    size_t position_ = 0;
    int lineNumber_ = 0;
};

}  // namespace btfracture
