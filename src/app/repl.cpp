#include "app/repl.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <sys/select.h>

#include <lua.hpp>
#include <readline/history.h>
#include <readline/readline.h>

#include "core/interrupt.h"

namespace froth::app {
namespace {

// ---- Ctrl-C while Lua runs (lua.c's laction/lstop, plus froth's engine flag) ----------------

lua_State* g_running = nullptr;            // the state the SIGINT handler hooks (lua.c globalL)
volatile std::sig_atomic_t g_sigint = 0;   // Ctrl-C seen while reading a line
volatile std::sig_atomic_t g_sigwinch = 0; // terminal resized while reading a line

void set_handler(int sig, void (*handler)(int)) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; // no SA_RESTART: pselect() at the prompt must return EINTR
    sigaction(sig, &sa, nullptr);
}

void interrupt_hook(lua_State* L, lua_Debug*);

// lua.c's laction: only async-signal-safe work here. The engine loops poll the flag between
// steps; the hook catches plain Lua loops. SIG_DFL makes a second Ctrl-C kill a process that
// is stuck in C code and serviced neither.
void on_sigint_running(int) {
    set_handler(SIGINT, SIG_DFL);
    froth::request_interrupt();
    lua_sethook(g_running, interrupt_hook,
                LUA_MASKCALL | LUA_MASKRET | LUA_MASKLINE | LUA_MASKCOUNT, 1);
}

// lua.c's lstop. Inside an evolution (its on_step callback), a first Ctrl-C is left to the
// engine loop, which stops after the current step and returns "interrupted"; a second one
// that nobody served yet raises here. If an engine loop already consumed the flag (and
// returned normally), the script goes on: re-arm Ctrl-C instead of raising.
void interrupt_hook(lua_State* L, lua_Debug*) {
    lua_sethook(L, nullptr, 0, 0);
    if (froth::engine_loop_active() && froth::interrupt_requests() == 1) {
        set_handler(SIGINT, on_sigint_running);
        return;
    }
    if (!froth::consume_interrupt()) {
        set_handler(SIGINT, on_sigint_running);
        return;
    }
    luaL_error(L, "interrupted!");
}

// lua.c's msghandler: error objects that are not strings get a __tostring or a type note.
int msghandler(lua_State* L) {
    const char* msg = lua_tostring(L, 1);
    if (msg == nullptr) {
        if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) return 1;
        msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    }
    luaL_traceback(L, L, msg, 1);
    return 1;
}

// ---- History: one entry per chunk, appended at once so os.exit() loses nothing ----------------

std::string g_history_file; // empty: history stays in memory

void init_history() {
    const char* env = std::getenv("FROTH_HISTORY"); // set but empty disables the file
    const char* home = std::getenv("HOME");
    if (env != nullptr)
        g_history_file = env;
    else if (home != nullptr && *home != '\0')
        g_history_file = std::string(home) + "/.froth_history";
    using_history();
    if (g_history_file.empty()) return;
    read_history(g_history_file.c_str());
    history_truncate_file(g_history_file.c_str(), 1000); // bounded across sessions
}

void save_history(const std::string& chunk) {
    if (chunk.empty()) return;
    add_history(chunk.c_str());
    if (g_history_file.empty()) return;
    // append_history() does not create the file; write_history() does. Failures (read-only
    // home, no home) are deliberately silent: the session must not suffer for them.
    if (append_history(1, g_history_file.c_str()) != 0) write_history(g_history_file.c_str());
}

// ---- Tab completion of globals, fields (a.b.<TAB>) and methods (obj:<TAB>) ----------------------

constexpr const char* kKeywords[] = {"and",   "break", "do",       "else", "elseif", "end",
                                     "false", "for",   "function", "goto", "if",     "in",
                                     "local", "nil",   "not",      "or",   "repeat", "return",
                                     "then",  "true",  "until",    "while"};

bool is_identifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (const char ch : s)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') return false;
    for (const char* kw : kKeywords)
        if (s == kw) return false;
    return true;
}

// Replaces the value on the top by its metatable's __index table; false (top popped) if none.
// Completion follows only __index *tables*, so it never runs user code.
bool to_index_table(lua_State* L) {
    if (lua_getmetatable(L, -1)) {
        lua_pushliteral(L, "__index");
        if (lua_rawget(L, -2) == LUA_TTABLE) {
            lua_replace(L, -3);
            lua_pop(L, 1);
            return true;
        }
        lua_pop(L, 2);
    }
    lua_pop(L, 1);
    return false;
}

// Replaces the value on the top by its field `key`, looked up raw along the __index chain.
bool to_field(lua_State* L, const std::string& key) {
    for (int depth = 0; depth < 8; ++depth) {
        if (lua_istable(L, -1)) {
            lua_pushlstring(L, key.data(), key.size());
            if (lua_rawget(L, -2) != LUA_TNIL) {
                lua_remove(L, -2);
                return true;
            }
            lua_pop(L, 1);
        }
        if (!to_index_table(L)) return false;
    }
    lua_pop(L, 1);
    return false;
}

struct Completion {
    std::string text;             // the word under the cursor, e.g. "froth.ve" or "c:st"
    std::vector<std::string> out; // full replacements, e.g. "froth.version"
};

// Adds the keys of the value on the top (and of its __index chain) that extend `partial`; pops.
void add_keys(lua_State* L, Completion& c, const std::string& head, const std::string& partial,
              bool methods_only) {
    const bool show_private = partial.rfind("__", 0) == 0; // __gc etc. only when asked for
    for (int depth = 0; depth < 8; ++depth) {
        if (lua_istable(L, -1)) {
            lua_pushnil(L);
            while (lua_next(L, -2) != 0) {
                const bool is_function = lua_isfunction(L, -1);
                if (lua_type(L, -2) == LUA_TSTRING) { // never lua_tostring a number key
                    const std::string key = lua_tostring(L, -2);
                    if (is_identifier(key) && key.rfind(partial, 0) == 0 &&
                        (show_private || key.rfind("__", 0) != 0) && (!methods_only || is_function))
                        c.out.push_back(head + key + (is_function ? "(" : ""));
                }
                lua_pop(L, 1);
            }
        }
        if (!to_index_table(L)) return;
    }
    lua_pop(L, 1);
}

// Runs under lua_pcall, so a memory error cannot unwind through readline's C frames.
int collect_completions(lua_State* L) {
    auto& c = *static_cast<Completion*>(lua_touserdata(L, 1));
    const auto sep = c.text.find_last_of(".:");
    lua_pushglobaltable(L);
    if (sep == std::string::npos) {
        for (const char* kw : kKeywords)
            if (std::string(kw).rfind(c.text, 0) == 0) c.out.emplace_back(kw);
        add_keys(L, c, "", c.text, false);
        return 0;
    }
    std::size_t start = 0; // walk "a.b.c" of "a.b.c:m"; a ':' inside the path is not completable
    while (start < sep) {
        const auto dot = c.text.find('.', start);
        const auto end = std::min(dot == std::string::npos ? sep : dot, sep);
        const std::string key = c.text.substr(start, end - start);
        if (key.find(':') != std::string::npos || !to_field(L, key)) return 0;
        start = end + 1;
    }
    add_keys(L, c, c.text.substr(0, sep + 1), c.text.substr(sep + 1), c.text[sep] == ':');
    return 0;
}

lua_State* g_repl = nullptr; // the state completion looks into
std::vector<std::string> g_matches;

char* next_match(const char*, int state) {
    static std::size_t i = 0;
    if (state == 0) i = 0;
    return i < g_matches.size() ? strdup(g_matches[i++].c_str()) : nullptr;
}

char** complete(const char* text, int, int) {
    rl_attempted_completion_over = 1;      // never fall back to file names
    rl_completion_append_character = '\0'; // functions get "(" instead of a space
    Completion c{text, {}};
    const int top = lua_gettop(g_repl);
    lua_pushcfunction(g_repl, collect_completions);
    lua_pushlightuserdata(g_repl, &c);
    if (lua_pcall(g_repl, 1, 0, 0) != LUA_OK) c.out.clear();
    lua_settop(g_repl, top);
    g_matches = std::move(c.out);
    return g_matches.empty() ? nullptr : rl_completion_matches(text, next_match);
}

// ---- Reading a line: readline's callback interface, so Ctrl-C can abandon the line ------------

enum class Read { line, eof, cancelled };

Read g_read = Read::line;
bool g_waiting = false;
std::string g_line;

void on_line(char* line) {
    g_waiting = false;
    g_read = line != nullptr ? Read::line : Read::eof;
    g_line = line != nullptr ? line : "";
    std::free(line);
    rl_callback_handler_remove(); // else readline redraws the prompt before the chunk runs
}

void on_prompt_signal(int sig) {
    (sig == SIGINT ? g_sigint : g_sigwinch) = 1;
}

// Ctrl-C at a prompt drops the line (and any unfinished chunk), like bash and python.
// Echo first: removing the handler may print a carriage return (bracketed-paste off).
void cancel_line() {
    rl_point = rl_end;
    rl_redisplay();
    std::fputs("^C", rl_outstream);
    rl_crlf();
    rl_free_line_state();
    rl_callback_sigcleanup();
    rl_callback_handler_remove();
    g_waiting = false;
    g_read = Read::cancelled;
}

// SIGINT and SIGWINCH stay blocked except inside pselect(), so no signal slips in between the
// flag test and the wait, and none lands inside readline's own code.
Read read_line(const std::string& prompt, std::string& line) {
    sigset_t blocked, old;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGINT);
    sigaddset(&blocked, SIGWINCH);
    sigprocmask(SIG_BLOCK, &blocked, &old);
    set_handler(SIGINT, on_prompt_signal);
    set_handler(SIGWINCH, on_prompt_signal);
    g_sigint = 0;
    g_waiting = true;
    rl_callback_handler_install(prompt.c_str(), on_line);
    while (g_waiting) {
        if (g_sigint != 0) {
            cancel_line();
            break;
        }
        if (g_sigwinch != 0) {
            g_sigwinch = 0;
            rl_resize_terminal();
        }
        const int fd = fileno(rl_instream);
        fd_set fds;
        FD_ZERO(&fds);
        FD_SET(fd, &fds);
        const int n = pselect(fd + 1, &fds, nullptr, nullptr, nullptr, &old);
        if (n > 0)
            rl_callback_read_char();
        else if (n < 0 && errno != EINTR)
            on_line(nullptr); // stdin gone: treat as end of input
    }
    set_handler(SIGINT, SIG_DFL); // idle: a Ctrl-C outside prompt and code behaves as usual
    set_handler(SIGWINCH, SIG_DFL);
    sigprocmask(SIG_SETMASK, &old, nullptr);
    line = g_line;
    return g_read;
}

// ---- lua.c's loadline: "return <line>;" first, then a statement with continuation lines --------

constexpr int kCancelled = -2; // Ctrl-C dropped the input: nothing to run
constexpr int kEndOfInput = -1;

std::string prompt(lua_State* L, bool first) {
    lua_getglobal(L, first ? "_PROMPT" : "_PROMPT2");
    const char* p = lua_tostring(L, -1);
    std::string result = p != nullptr ? p : (first ? "> " : ">> ");
    lua_pop(L, 1);
    return result;
}

// lua.c's incomplete: a syntax error at "<eof>" means the chunk wants more lines.
bool incomplete(lua_State* L, int status) {
    if (status != LUA_ERRSYNTAX) return false;
    std::size_t len = 0;
    const char* msg = lua_tolstring(L, -1, &len);
    constexpr std::size_t mark = sizeof("<eof>") - 1;
    if (len < mark || std::strcmp(msg + len - mark, "<eof>") != 0) return false;
    lua_pop(L, 1);
    return true;
}

// Leaves the compiled chunk (status LUA_OK) or the error message on the top.
int load_line(lua_State* L) {
    std::string typed;
    const Read r = read_line(prompt(L, true), typed);
    if (r != Read::line) return r == Read::eof ? kEndOfInput : kCancelled;
    // "=expr" is 5.2's spelling of "return expr" (lua.c's pushline).
    std::string chunk = typed.rfind('=', 0) == 0 ? "return " + typed.substr(1) : typed;
    const std::string with_return = "return " + chunk + ";";
    if (luaL_loadbuffer(L, with_return.data(), with_return.size(), "=stdin") == LUA_OK) {
        save_history(typed);
        return LUA_OK;
    }
    lua_pop(L, 1);
    for (;;) {
        const int status = luaL_loadbuffer(L, chunk.data(), chunk.size(), "=stdin");
        std::string more;
        if (!incomplete(L, status)) {
            save_history(typed);
            return status;
        }
        const Read next = read_line(prompt(L, false), more);
        if (next == Read::cancelled) return kCancelled;
        if (next == Read::eof) { // report the "<eof>" error rather than silently dropping
            save_history(typed);
            return luaL_loadbuffer(L, chunk.data(), chunk.size(), "=stdin");
        }
        chunk += "\n" + more;
        typed += "\n" + more;
    }
}

// Replaces each table result by its readable text (lua/froth/pretty.lua: reports and results
// print as {energy = ..., volumes = {...}}, not "table: 0x..."); without the module, as is.
void prettify_tables(lua_State* L, int base) {
    bool any = false;
    for (int i = base + 1; i <= lua_gettop(L); ++i) any = any || lua_type(L, i) == LUA_TTABLE;
    if (!any) return;
    lua_getglobal(L, "require");
    lua_pushstring(L, "froth.pretty");
    if (lua_pcall(L, 1, 1, 0) != LUA_OK || !lua_istable(L, -1)) {
        lua_pop(L, 1);
        return;
    }
    lua_getfield(L, -1, "format");
    const int format = lua_gettop(L);
    for (int i = base + 1; i < format - 1; ++i) {
        if (lua_type(L, i) != LUA_TTABLE) continue;
        lua_pushvalue(L, format);
        lua_pushvalue(L, i);
        if (lua_pcall(L, 1, 1, 0) == LUA_OK && lua_type(L, -1) == LUA_TSTRING)
            lua_replace(L, i);
        else
            lua_pop(L, 1);
    }
    lua_pop(L, 2);
}

// lua.c's l_print: results go through the global print, so __tostring and overrides apply.
void print_results(lua_State* L, int base) {
    const int n = lua_gettop(L) - base;
    if (n <= 0) return;
    luaL_checkstack(L, LUA_MINSTACK, "too many results to print");
    prettify_tables(L, base);
    lua_getglobal(L, "print");
    lua_insert(L, base + 1);
    if (lua_pcall(L, n, 0, 0) != LUA_OK)
        std::fprintf(stderr, "error calling 'print' (%s)\n", lua_tostring(L, -1));
}

} // namespace

int docall(lua_State* L, int narg, int nres) {
    const int base = lua_gettop(L) - narg;
    lua_pushcfunction(L, msghandler);
    lua_insert(L, base);
    g_running = L;
    set_handler(SIGINT, on_sigint_running);
    const int status = lua_pcall(L, narg, nres, base);
    set_handler(SIGINT, SIG_DFL);
    // A Ctrl-C that arrived as the call ended must not hit the next chunk or engine loop.
    if (lua_gethook(L) == interrupt_hook) lua_sethook(L, nullptr, 0, 0);
    froth::consume_interrupt();
    lua_remove(L, base);
    return status;
}

int report(lua_State* L, int status, const char* progname) {
    if (status == LUA_OK) return status;
    const char* msg = lua_tostring(L, -1);
    if (progname != nullptr) std::fprintf(stderr, "%s: ", progname);
    std::fprintf(stderr, "%s\n", msg != nullptr ? msg : "(error object is not a string)");
    std::fflush(stderr);
    lua_pop(L, 1);
    return status;
}

void run_repl(lua_State* L) {
    g_repl = L;
    rl_readline_name = "froth"; // for $if froth in ~/.inputrc
    rl_attempted_completion_function = complete;
    static char breaks[] = " \t\n\"\\'`@$><=;|&{(,+-*/%^#~[]"; // not '.' or ':'
    rl_completer_word_break_characters = breaks;
    init_history();
    const int base = lua_gettop(L);
    int status;
    while ((status = load_line(L)) != kEndOfInput) {
        if (status == kCancelled) continue;
        if (status == LUA_OK) status = docall(L, 0, LUA_MULTRET);
        if (status == LUA_OK)
            print_results(L, base);
        else
            report(L, status, nullptr); // lua.c: no program name in interactive mode
        lua_settop(L, base);
    }
    std::fputs("\n", stdout);
    std::fflush(stdout);
}

} // namespace froth::app
