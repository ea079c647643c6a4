#include "io/text_file.h"

#include "core/errors.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace froth::io {
namespace fs = std::filesystem;

TextBuffer& TextBuffer::operator<<(double x) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    text_.append(buf, r.ptr);
    return *this;
}

TextBuffer& TextBuffer::operator<<(long long n) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, n);
    text_.append(buf, r.ptr);
    return *this;
}

TextBuffer& TextBuffer::xml_escaped(std::string_view s) {
    for (char c : s) {
        switch (c) {
        case '&': text_ += "&amp;"; break;
        case '<': text_ += "&lt;"; break;
        case '>': text_ += "&gt;"; break;
        case '"': text_ += "&quot;"; break;
        case '\'': text_ += "&apos;"; break;
        default: text_ += c;
        }
    }
    return *this;
}

void ensure_parent_directory(const std::string& path, const char* op) {
    const fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) return;
    std::error_code ec;
    if (fs::is_directory(dir, ec)) return;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw IoError(std::string(op) + ": cannot create directory '" + dir.string() +
                      "': " + (ec ? ec.message() : std::string("not a directory")));
}

namespace {

[[noreturn]] void fail(const char* op, const std::string& what, int err) {
    throw IoError(std::string(op) + ": " + what + ": " + std::strerror(err));
}

} // namespace

void write_text_file(const std::string& path, const std::string& text, const char* op) {
    if (path.empty()) throw IoError(std::string(op) + ": empty file name");
    ensure_parent_directory(path, op);
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) fail(op, "cannot open '" + path + "' for writing", errno);
    errno = 0;
    const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    int err = errno;
    const bool closed = std::fclose(f) == 0;
    if (!closed && err == 0) err = errno;
    if (!wrote || !closed) {
        std::remove(tmp.c_str());
        fail(op, "cannot write '" + path + "'", err ? err : EIO);
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw IoError(std::string(op) + ": cannot write '" + path + "': " + ec.message());
    }
}

} // namespace froth::io
