#pragma once
/// The lua.c-style runner behind the `froth` executable: protected calls with a traceback,
/// Ctrl-C handling, and the interactive read-eval-print loop (GNU readline).

struct lua_State;

namespace froth::app {

/// Calls the function that sits below the top `narg` values, as lua.c's docall does: a message
/// handler appends a traceback, and Ctrl-C during the call first asks the engine loops to stop
/// (froth::request_interrupt) and, if Lua code is running, raises "interrupted!".
/// Returns the lua_pcall status; on error the message (with traceback) is on the top.
int docall(lua_State* L, int narg, int nres);

/// If `status` is not LUA_OK, prints the message on the top of the stack to stderr, prefixed
/// with "<progname>: " unless progname is null, and pops it. Returns `status`.
int report(lua_State* L, int status, const char* progname);

/// Reads, evaluates and prints chunks from the terminal until end of input, exactly like
/// lua.c's doREPL: prompts `_PROMPT`/`_PROMPT2`, `return <line>` first, continuation lines
/// while the syntax error ends in "<eof>". History lives in $FROTH_HISTORY, else
/// ~/.froth_history; an unreadable or unwritable file only disables persistence.
void run_repl(lua_State* L);

} // namespace froth::app
