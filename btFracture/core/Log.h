// SPDX-License-Identifier: Zlib
#pragma once
// Minimal logging: every clamp, fix-up or fallback in btFracture goes through here so that
// nothing changes silently. Apps may redirect messages with setLogSink().
#include <functional>
#include <sstream>
#include <string>

namespace btfracture {

enum class LogLevel { Debug = 0, Info = 1, Warning = 2, Error = 3 };

using LogSink = std::function<void(LogLevel, const std::string&)>;

// Replaces the sink (default: stderr). Pass nullptr to restore the default.
void setLogSink(LogSink sink);
// Messages below this level are dropped (default: Info).
void setLogLevel(LogLevel level);
LogLevel logLevel();
void log(LogLevel level, const std::string& message);

// Builds a message from stream pieces: logf(LogLevel::Warning, "mesh ", name, " flipped").
template <class... Parts>
void logf(LogLevel level, const Parts&... parts) {
    if (level < logLevel()) return;
    std::ostringstream out;
    (out << ... << parts);
    log(level, out.str());
}

}  // namespace btfracture
