// froth: the command-line front end. It behaves like the standalone `lua` (lua.c 5.4): the same
// options, the same `arg` table, the same REPL, with the froth module preloaded.
//
// Sample runs:  froth                      (REPL)
//               froth datafiles/double_bubble.lua --steps 200
//               froth -e 'print(froth.version)'
//               echo 'print(40 + 2)' | froth

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <sched.h>
#include <unistd.h>

#include <lua.hpp>

#include "app/repl.h"
#include "bindings/froth_lua.h"

namespace {

constexpr const char* kProgname = "froth";

// OpenBLAS (Debian's pthread build, CHOLMOD's BLAS) starts a worker thread per CPU in its own
// constructor, before main, and the workers spin in sched_yield for about 0.1 s even after the
// solvers ask for one thread (solvers/sparse_solvers.cpp): 12% of a short run's wall time and
// half its system time (docs/benchmarks.md, "Statics"). Its constructor counts the CPUs of the
// process's affinity mask; environment variables cannot be set this early (glibc's getenv and
// setenv work only from the libraries' constructors on). So the executable's .preinit_array,
// which runs before every library constructor, narrows the mask to one CPU, and main()
// restores it. Not done when the user chose thread counts (OPENBLAS_NUM_THREADS,
// GOTO_NUM_THREADS, OMP_NUM_THREADS), which OpenBLAS would otherwise cap at the one CPU.
cpu_set_t g_cpus;
bool g_narrowed = false;
bool chooses_threads(char** envp) {
    for (char** e = envp; e != nullptr && *e != nullptr; ++e)
        for (const char* name : {"OPENBLAS_NUM_THREADS=", "GOTO_NUM_THREADS=", "OMP_NUM_THREADS="})
            if (std::strncmp(*e, name, std::strlen(name)) == 0) return true;
    return false;
}
void start_blas_single_threaded(int, char**, char** envp) {
    if (chooses_threads(envp) || sched_getaffinity(0, sizeof g_cpus, &g_cpus) != 0) return;
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
        if (CPU_ISSET(cpu, &g_cpus)) {
            cpu_set_t one;
            CPU_ZERO(&one);
            CPU_SET(cpu, &one);
            g_narrowed = sched_setaffinity(0, sizeof one, &one) == 0;
            return;
        }
}
[[gnu::used, gnu::section(".preinit_array")]] void (*const preinit_blas)(int, char**, char**) =
    start_blas_single_threaded;

// Bits of lua.c's collectargs, plus the GNU-style --help and --version.
enum : unsigned {
    has_error = 1u << 0,
    has_i = 1u << 1,
    has_v = 1u << 2,
    has_e = 1u << 3,
    has_E = 1u << 4,
    has_W = 1u << 5,
    has_help = 1u << 6,
    has_version = 1u << 7,
};

void print_usage(std::FILE* out) {
    std::fprintf(
        out,
        "usage: %s [options] [script [args]]\n"
        "Available options are:\n"
        "  -e stat   execute string 'stat'\n"
        "  -i        enter interactive mode after executing 'script'\n"
        "  -l mod    require library 'mod' into global 'mod'\n"
        "  -l g=mod  require library 'mod' into global 'g'\n"
        "  -v        show version information\n"
        "  -E        ignore environment variables\n"
        "  -W        turn warnings on\n"
        "  --        stop handling options\n"
        "  -         stop handling options and execute stdin\n"
        "  --help    show this help and exit (also -h)\n"
        "  --version show version information and exit\n"
        "With no script and no -e, froth reads stdin: a REPL on a terminal, else a chunk.\n"
        "The Lua API (the global 'froth' table) is described in docs/lua_api.md.\n",
        kProgname);
}

// lua.c's print_usage: name the offending option, then the usage, all on stderr.
void print_bad_option(const char* option) {
    if ((option[1] == 'e' || option[1] == 'l') && option[2] == '\0')
        std::fprintf(stderr, "%s: '%s' needs argument\n", kProgname, option);
    else
        std::fprintf(stderr, "%s: unrecognized option '%s'\n", kProgname, option);
    print_usage(stderr);
}

void print_version() {
    std::printf("%s %s\n", kProgname, froth::lua::version());
}

void print_banner() {
    std::printf("%s %s (%s) -- surface clusters by parametric FEM; type help() or see "
                "docs/lua_api.md\n",
                kProgname, froth::lua::version(), LUA_VERSION);
    std::fflush(stdout);
}

bool is_flag(const char* arg, char letter) {
    return arg[1] == letter && arg[2] == '\0';
}

// lua.c's collectargs: returns the option bits; *first is the script's index in argv (argc if
// none), or the bad option's index on has_error. Options stop at the first non-option.
unsigned collect_args(char** argv, int* first) {
    unsigned args = 0;
    int i = 1;
    for (; argv[i] != nullptr; ++i) {
        *first = i;
        const char* a = argv[i];
        if (a[0] != '-') return args;
        if (std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0) return has_help;
        if (std::strcmp(a, "--version") == 0) return has_version;
        if (std::strcmp(a, "--") == 0) {
            *first = i + 1;
            return args;
        }
        if (a[1] == '\0') return args; // "-": the script is stdin
        if (is_flag(a, 'E'))
            args |= has_E;
        else if (is_flag(a, 'W'))
            args |= has_W;
        else if (is_flag(a, 'i'))
            args |= has_i | has_v; // lua.c: -i implies -v
        else if (is_flag(a, 'v'))
            args |= has_v;
        else if (a[1] == 'e' || a[1] == 'l') {
            if (a[1] == 'e') args |= has_e;
            // The argument is glued ("-eprint(1)") or the next word, which must not be an option.
            if (a[2] == '\0' && (argv[++i] == nullptr || argv[i][0] == '-')) {
                *first = i - 1;
                return has_error;
            }
        } else {
            return has_error;
        }
    }
    *first = i;
    return args;
}

// lua.c's createargtable: arg[0] is the script (the interpreter when there is none), script
// arguments are positive, the interpreter and its options negative.
void create_arg_table(lua_State* L, char** argv, int argc, int script) {
    if (script == argc) script = 0;
    lua_createtable(L, argc - (script + 1), script + 1);
    for (int i = 0; i < argc; ++i) {
        lua_pushstring(L, argv[i]);
        lua_rawseti(L, -2, i - script);
    }
    lua_setglobal(L, "arg");
}

int do_chunk(lua_State* L, int status) {
    if (status == LUA_OK) status = froth::app::docall(L, 0, 0);
    return froth::app::report(L, status, kProgname);
}

// lua.c's dolibrary: `-l g=mod` stores require("mod") in global g, `-l mod` in global mod.
int do_library(lua_State* L, const char* spec) {
    const char* eq = std::strchr(spec, '=');
    const std::string global = eq != nullptr ? std::string(spec, eq) : std::string(spec);
    lua_getglobal(L, "require");
    lua_pushstring(L, eq != nullptr ? eq + 1 : spec);
    const int status = froth::app::docall(L, 1, 1);
    if (status == LUA_OK) lua_setglobal(L, global.c_str());
    return froth::app::report(L, status, kProgname);
}

// lua.c's runargs: -e and -l run in command-line order, before the script.
bool run_args(lua_State* L, char** argv, int n) {
    for (int i = 1; i < n; ++i) {
        const char option = argv[i][1];
        if (option != 'e' && option != 'l') continue;
        const char* extra = argv[i][2] != '\0' ? argv[i] + 2 : argv[++i];
        const int status =
            option == 'e'
                ? do_chunk(L, luaL_loadbuffer(L, extra, std::strlen(extra), "=(command line)"))
                : do_library(L, extra);
        if (status != LUA_OK) return false;
    }
    return true;
}

// lua.c's handle_script: the script gets arg[1..#arg] as `...`.
int handle_script(lua_State* L, char** argv) {
    const char* fname = argv[0];
    if (std::strcmp(fname, "-") == 0 && std::strcmp(argv[-1], "--") != 0) fname = nullptr;
    int status = luaL_loadfile(L, fname);
    if (status == LUA_OK) {
        if (lua_getglobal(L, "arg") != LUA_TTABLE) luaL_error(L, "'arg' is not a table");
        const int n = static_cast<int>(luaL_len(L, -1));
        luaL_checkstack(L, n + 3, "too many arguments to script");
        for (int i = 1; i <= n; ++i)
            lua_rawgeti(L, -i, i);
        lua_remove(L, -n - 1);
        status = froth::app::docall(L, n, 0);
    }
    return froth::app::report(L, status, kProgname);
}

// lua.c's pmain, run in protected mode so that every Lua error is caught and reported.
int pmain(lua_State* L) {
    const int argc = static_cast<int>(lua_tointeger(L, 1));
    char** argv = static_cast<char**>(lua_touserdata(L, 2));
    int script = argc;
    const unsigned args = collect_args(argv, &script);
    luaL_checkversion(L);
    if (args & has_error) {
        print_bad_option(argv[script]);
        return 0;
    }
    if (args & (has_help | has_version)) {
        if (args & has_help)
            print_usage(stdout);
        else
            print_version();
        lua_pushboolean(L, 1);
        return 1;
    }
    if (args & has_i)
        print_banner();
    else if (args & has_v)
        print_version();
    if (args & has_E) { // must precede luaL_openlibs: package reads it to skip LUA_PATH
        lua_pushboolean(L, 1);
        lua_setfield(L, LUA_REGISTRYINDEX, "LUA_NOENV");
    }
    luaL_openlibs(L);
    froth::lua::open_froth(L); // also the global help (lua/froth/help.lua)
    create_arg_table(L, argv, argc, script);
    if (args & has_W) lua_warning(L, "@on", 0);
    if (!run_args(L, argv, script)) return 0;
    if (script < argc && handle_script(L, argv + script) != LUA_OK) return 0;
    if (args & has_i) {
        froth::app::run_repl(L);
    } else if (script == argc && !(args & (has_e | has_v))) {
        if (isatty(STDIN_FILENO)) {
            print_banner();
            froth::app::run_repl(L);
        } else if (do_chunk(L, luaL_loadfile(L, nullptr)) != LUA_OK) {
            return 0; // unlike lua.c, a failing piped chunk gives exit status 1
        }
    }
    lua_pushboolean(L, 1);
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (g_narrowed) sched_setaffinity(0, sizeof g_cpus, &g_cpus);
    lua_State* L = luaL_newstate();
    if (L == nullptr) {
        std::fprintf(stderr, "%s: cannot create state: not enough memory\n", kProgname);
        return EXIT_FAILURE;
    }
    lua_pushcfunction(L, pmain);
    lua_pushinteger(L, argc);
    lua_pushlightuserdata(L, argv);
    const int status = lua_pcall(L, 2, 1, 0);
    const bool ok = status == LUA_OK && lua_toboolean(L, -1);
    froth::app::report(L, status, kProgname);
    lua_close(L);
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
