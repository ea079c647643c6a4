#pragma once
/// Shared helpers of the froth_io writers: a fast text buffer (shortest round-trip number
/// formatting via std::to_chars) and an atomic whole-file write that reports IoError.

#include <cstdint>
#include <string>
#include <string_view>

namespace froth::io {

/// Append-only text buffer. Doubles are written in the shortest form that reads back to the
/// identical value (std::to_chars), so an ASCII file loses no precision.
class TextBuffer {
  public:
    /// Reserve room for about n characters.
    void reserve(std::size_t n) { text_.reserve(n); }
    TextBuffer& operator<<(std::string_view s) {
        text_.append(s);
        return *this;
    }
    TextBuffer& operator<<(char c) {
        text_.push_back(c);
        return *this;
    }
    /// Shortest round-trip decimal form of x ("nan"/"inf" for non-finite values).
    TextBuffer& operator<<(double x);
    TextBuffer& operator<<(int n) { return *this << static_cast<long long>(n); }
    TextBuffer& operator<<(long long n);
    /// Appends s with the XML special characters (& < > " ') escaped.
    TextBuffer& xml_escaped(std::string_view s);
    const std::string& str() const { return text_; }

  private:
    std::string text_;
};

/// Creates the parent directory of path (and its parents) if it is missing.
/// \throw IoError "<op>: cannot create directory 'dir': <reason>"
void ensure_parent_directory(const std::string& path, const char* op = "write");

/// Writes text to path, creating the parent directory if needed. The text goes to a unique
/// temporary file beside path (mkstemp: ".name.XXXXXX"), is fsynced, and is renamed over path,
/// and the folder is fsynced: a reader (ParaView watching a series) never sees a half-written
/// file, a crash leaves the old file or the new one, and concurrent writers never share a
/// temporary.
/// \throw IoError "<op>: cannot open 'path' for writing: <strerror>" (or "cannot write")
void write_text_file(const std::string& path, const std::string& text, const char* op = "write");

/// The whole contents of path, a regular file of at most max_bytes bytes (devices, pipes and
/// directories are refused before they are opened for reading, so nothing can block or stream
/// forever).
/// \throw IoError "<op>: cannot open 'path': <reason>" ("No such file or directory", "Is a
///        directory", "not a regular file", "larger than the limit of N bytes", ...)
std::string read_text_file(const std::string& path, std::uintmax_t max_bytes, const char* op);

} // namespace froth::io
