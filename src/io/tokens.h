#pragma once
/// The validating tokenizer of froth's readers (msh_reader.cpp, state_file.cpp): tokens with the
/// line they are on for messages, numbers parsed strictly, and counts checked against the bytes
/// left before anything is sized by them, so no file can make a reader allocate without bound.

#include "core/errors.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace froth::io {

/// Counts read from the file are checked against the bytes left (each item needs at least
/// `tokens` tokens of two bytes) before anything is sized by them. Errors are IoError
/// "<where>line N: <what>".
class Tokens {
  public:
    Tokens(std::string_view text, std::string where)
        : p_(text.data()), end_(p_ + text.size()), where_(std::move(where)) {}

    bool at_end() {
        skip_space();
        return p_ == end_;
    }

    std::string_view next(const char* what) {
        skip_space();
        if (p_ == end_) fail(std::string("unexpected end of file, expected ") + what);
        const char* start = p_;
        while (p_ != end_ && !is_space(*p_))
            ++p_;
        return {start, static_cast<std::size_t>(p_ - start)};
    }

    /// The rest of the current line without its leading blanks (a name that may hold spaces).
    std::string_view rest_of_line(const char* what) {
        while (p_ != end_ && (*p_ == ' ' || *p_ == '\t'))
            ++p_;
        const char* start = p_;
        while (p_ != end_ && *p_ != '\n' && *p_ != '\r')
            ++p_;
        if (p_ == start) fail(std::string("expected ") + what);
        return {start, static_cast<std::size_t>(p_ - start)};
    }

    long long integer(const char* what, long long lo, long long hi) {
        const std::string_view t = next(what);
        long long v = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size())
            fail(std::string("expected ") + what + " (an integer), got '" + shown(t) + "'");
        if (v < lo || v > hi)
            fail(std::string(what) + " " + std::string(t) + " is out of range [" +
                 std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return v;
    }

    int tag(const char* what) {
        constexpr long long big = std::numeric_limits<int>::max(); // symmetric: tags may be signed
        return static_cast<int>(integer(what, -big, big));
    }

    double real(const char* what) { return real(next(what), what); }

    /// Token t (already read) as a finite number.
    double real(std::string_view t, const char* what) const {
        double v = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
            fail(std::string("expected ") + what + " (a finite number), got '" + shown(t) + "'");
        return v;
    }

    /// A count of items of `tokens` tokens each that must fit in the rest of the file.
    std::size_t count(const char* what, int tokens) {
        const long long n = integer(what, 0, std::numeric_limits<int>::max());
        const auto left = static_cast<unsigned long long>(end_ - p_);
        if (static_cast<unsigned long long>(n) * tokens * 2 > left + 1)
            fail(std::string(what) + " " + std::to_string(n) + " cannot fit in the " +
                 std::to_string(left) + " bytes left in the file");
        return static_cast<std::size_t>(n);
    }

    void expect(std::string_view word) {
        const std::string_view t = next(std::string(word).c_str());
        if (t != word) fail("expected " + std::string(word) + ", got '" + shown(t) + "'");
    }

    /// Skips to the line after "$End<name>" (a section froth does not read).
    void skip_section(std::string_view name) {
        const std::string end_tag = "$End" + std::string(name);
        while (!at_end())
            if (next(end_tag.c_str()) == end_tag) return;
        fail("section $" + std::string(name) + " has no " + end_tag);
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw IoError(where_ + "line " + std::to_string(line_) + ": " + what);
    }

  private:
    static bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }
    static std::string shown(std::string_view t) {
        return std::string(t.substr(0, 40)) + (t.size() > 40 ? "..." : "");
    }
    void skip_space() {
        while (p_ != end_ && is_space(*p_))
            line_ += *p_++ == '\n';
    }
    const char* p_;
    const char* end_;
    std::string where_;
    long long line_ = 1;
};

} // namespace froth::io
