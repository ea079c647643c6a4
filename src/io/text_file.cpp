#include "io/text_file.h"

#include "core/errors.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

namespace {

/// write(2) all of text to fd; false (errno set) on failure.
bool write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            if (w == 0) errno = EIO;
            return false;
        }
        done += static_cast<std::size_t>(w);
    }
    return true;
}

void fsync_directory(const fs::path& dir) {
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return; // the rename has happened; durability of the entry is best effort
    ::fsync(fd);
    ::close(fd);
}

} // namespace

// A unique temporary beside the target (mkstemp: no clobbering of a user's file, no two
// writers sharing one), flushed to disk (fsync) before the rename, so a crash or power loss
// leaves the old file or the new one, never a truncated mix; then the folder's entry is synced.
void write_text_file(const std::string& path, const std::string& text, const char* op) {
    if (path.empty()) throw IoError(std::string(op) + ": empty file name");
    ensure_parent_directory(path, op);
    const fs::path target(path);
    std::string name = ".";
    name += target.filename().string();
    name += ".XXXXXX";
    std::string tmp = (target.parent_path() / name).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) fail(op, "cannot open '" + path + "' for writing", errno);
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask); // mkstemp makes 0600; a written file gets the usual mode
    const bool wrote = write_all(fd, text) && ::fsync(fd) == 0;
    int err = errno;
    const bool closed = ::close(fd) == 0;
    if (!closed && wrote) err = errno;
    if (!wrote || !closed) {
        ::unlink(tmp.c_str());
        fail(op, "cannot write '" + path + "'", err ? err : EIO);
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        err = errno;
        ::unlink(tmp.c_str());
        fail(op, "cannot write '" + path + "'", err);
    }
    fsync_directory(target.parent_path());
}

std::string read_text_file(const std::string& path, std::uintmax_t max_bytes, const char* op) {
    const std::string prefix = std::string(op) + ": cannot open '" + path + "': ";
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) throw IoError(prefix + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw IoError(prefix + std::strerror(EISDIR));
    if (!S_ISREG(st.st_mode)) throw IoError(prefix + "not a regular file");
    if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        throw IoError(prefix + "larger than the limit of " + std::to_string(max_bytes) + " bytes");
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw IoError(prefix + std::strerror(errno));
    struct stat again {};
    if (::fstat(fd, &again) != 0 || !S_ISREG(again.st_mode)) { // replaced since the stat
        ::close(fd);
        throw IoError(prefix + "not a regular file");
    }
    std::string text(static_cast<std::size_t>(std::min<std::uintmax_t>(again.st_size, max_bytes)), '\0');
    std::size_t got = 0;
    while (got < text.size()) { // a file that shrinks meanwhile ends early; one that grows is cut
        const ssize_t r = ::read(fd, text.data() + got, text.size() - got);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) {
            const int err = errno;
            ::close(fd);
            throw IoError(std::string(op) + ": cannot read '" + path + "': " + std::strerror(err));
        }
        if (r == 0) break;
        got += static_cast<std::size_t>(r);
    }
    ::close(fd);
    text.resize(got);
    return text;
}

} // namespace froth::io
