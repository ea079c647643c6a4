// run_isolated: fork, build in the child, send the spec through a pipe, wait interruptibly.
#include "builders/isolated.h"

#include "core/errors.h"
#include "core/interrupt.h"

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <string_view>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace froth {
namespace {

InterruptFlag g_flag{&interrupt_requests, &consume_interrupt};

// The message: one status byte, then either a ClusterSpec or an error (kind byte + text).
enum : char { kSpec = 'S', kError = 'E' };
enum ErrorKind : char {
    kInvalid = 'I',
    kTopology = 'T',
    kGeometry = 'G',
    kIo = 'O',
    kSolver = 'V',
    kOther = 'X'
};

class Writer {
  public:
    template <class T> void put(const T& x) {
        const char* p = reinterpret_cast<const char*>(&x);
        bytes_.append(p, sizeof(T));
    }
    void put_string(const std::string& s) {
        put<std::uint64_t>(s.size());
        bytes_ += s;
    }
    const std::string& bytes() const { return bytes_; }

  private:
    std::string bytes_;
};

class Reader {
  public:
    explicit Reader(std::string_view b) : b_(b) {}
    template <class T> T get() {
        if (b_.size() - at_ < sizeof(T))
            throw GeometryError("meshing: the child's message is truncated");
        T x;
        std::memcpy(&x, b_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return x;
    }
    std::size_t count(std::size_t item_bytes) { // bounded by what is left: no huge allocation
        const auto n = get<std::uint64_t>();
        if (n > (b_.size() - at_) / item_bytes)
            throw GeometryError("meshing: the child's message is malformed");
        return static_cast<std::size_t>(n);
    }
    std::string get_string() {
        const std::size_t n = count(1);
        std::string s(b_.substr(at_, n));
        at_ += n;
        return s;
    }

  private:
    std::string_view b_;
    std::size_t at_ = 0;
};

std::string encode(const ClusterSpec& spec) {
    Writer w;
    w.put(kSpec);
    w.put<std::uint64_t>(spec.vertices.size());
    for (const Vec3& x : spec.vertices)
        w.put(x[0]), w.put(x[1]), w.put(x[2]);
    w.put<std::uint64_t>(spec.surfaces.size());
    for (const ClusterSpec::Surface& s : spec.surfaces) {
        w.put(s.sigma);
        w.put<std::uint64_t>(s.triangles.size());
        for (const Tri& t : s.triangles)
            w.put(t[0]), w.put(t[1]), w.put(t[2]);
    }
    w.put<std::uint64_t>(spec.bodies.size());
    for (const std::vector<int>& b : spec.bodies) {
        w.put<std::uint64_t>(b.size());
        for (int s : b)
            w.put(s);
    }
    return w.bytes();
}

ClusterSpec decode_spec(Reader& r) {
    ClusterSpec spec;
    spec.vertices.resize(r.count(3 * sizeof(double)));
    for (Vec3& x : spec.vertices)
        for (int d = 0; d < 3; ++d)
            x[d] = r.get<double>();
    spec.surfaces.resize(r.count(sizeof(double) + 8));
    for (ClusterSpec::Surface& s : spec.surfaces) {
        s.sigma = r.get<double>();
        s.triangles.resize(r.count(3 * sizeof(int)));
        for (Tri& t : s.triangles)
            for (int k = 0; k < 3; ++k)
                t[k] = r.get<int>();
    }
    spec.bodies.resize(r.count(8));
    for (std::vector<int>& b : spec.bodies) {
        b.resize(r.count(sizeof(int)));
        for (int& s : b)
            s = r.get<int>();
    }
    return spec;
}

std::string encode_error(ErrorKind kind, const std::string& what) {
    Writer w;
    w.put(kError);
    w.put(kind);
    w.put_string(what);
    return w.bytes();
}

[[noreturn]] void rethrow(ErrorKind kind, const std::string& what) {
    switch (kind) {
    case kInvalid:
        throw InvalidInput(what);
    case kTopology:
        throw TopologyError(what);
    case kGeometry:
        throw GeometryError(what);
    case kIo:
        throw IoError(what);
    case kSolver:
        throw SolverError(what);
    default:
        throw Error(what);
    }
}

void write_all(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return; // the parent went away: nothing to tell
        done += static_cast<std::size_t>(w);
    }
}

// The child: build, send, and leave with _exit (no atexit handlers, no flushing of the
// parent's stdio buffers a second time, no LeakSanitizer report of the parent's heap).
[[noreturn]] void child(int fd, const std::function<ClusterSpec()>& build) {
    std::signal(SIGINT, SIG_IGN); // the parent serves Ctrl-C by killing us
    std::string message;
    try {
        message = encode(build());
    } catch (const InvalidInput& e) {
        message = encode_error(kInvalid, e.what());
    } catch (const TopologyError& e) {
        message = encode_error(kTopology, e.what());
    } catch (const GeometryError& e) {
        message = encode_error(kGeometry, e.what());
    } catch (const IoError& e) {
        message = encode_error(kIo, e.what());
    } catch (const SolverError& e) {
        message = encode_error(kSolver, e.what());
    } catch (const std::exception& e) {
        message = encode_error(kOther, e.what());
    } // anything else ends the child in std::terminate, which the parent reports as a signal
    write_all(fd, message);
    ::close(fd);
    ::_exit(0);
}

void stop_child(pid_t pid) {
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
}

/// Reads the child's whole message, polling for Ctrl-C every 50 ms.
std::string receive(int fd, pid_t pid, const std::string& op) {
    std::string bytes;
    char buf[1 << 16];
    for (;;) {
        if (g_flag.requests() > 0) {
            g_flag.consume();
            stop_child(pid);
            throw Interrupted(op +
                              ": interrupted (Ctrl-C) while gmsh was meshing; nothing was built");
        }
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, 50);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return bytes; // EOF: the child is done (or died)
        bytes.append(buf, static_cast<std::size_t>(n));
    }
}

} // namespace

void use_interrupt_flag(const InterruptFlag& flag) {
    g_flag = flag;
}

ClusterSpec run_isolated(const std::string& op, const std::function<ClusterSpec()>& build) {
    int fds[2];
    if (::pipe(fds) != 0)
        throw GeometryError(op + ": cannot start the meshing process: " + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int err = errno;
        ::close(fds[0]), ::close(fds[1]);
        throw GeometryError(op + ": cannot start the meshing process: " + std::strerror(err));
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], build);
    }
    ::close(fds[1]);
    struct Closer { // the read end, also when receive throws (Ctrl-C)
        int fd;
        ~Closer() { ::close(fd); }
    } read_end{fds[0]};
    const std::string bytes = receive(read_end.fd, pid, op);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status))
        throw GeometryError(op + ": gmsh crashed while meshing (signal " +
                            std::to_string(WTERMSIG(status)) + ": " + strsignal(WTERMSIG(status)) +
                            "); nothing was built");
    if (bytes.empty()) throw GeometryError(op + ": the meshing process ended without a result");
    Reader r(bytes);
    if (r.get<char>() == kError) {
        const auto kind = static_cast<ErrorKind>(r.get<char>());
        rethrow(kind, r.get_string());
    }
    return decode_spec(r);
}

} // namespace froth
