#!/usr/bin/env bash
# Command-line behaviour of the froth executable (the non-interactive half of lua.c's).
# Usage: tests/app/cli_test.sh path/to/froth      Exit status 0 iff every check passes.

set -u
FROTH=${1:?usage: $0 path/to/froth}
[[ -x $FROTH ]] || { echo "cli_test: $FROTH is not executable" >&2; exit 2; }

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
passed=0
failed=0

# check NAME EXPECTED_STATUS STDOUT_PATTERN STDERR_PATTERN -- COMMAND...
# Patterns are grep -E regexes; an empty pattern skips that stream.
check() {
    local name=$1 want_rc=$2 out_re=$3 err_re=$4
    shift 5
    local rc=0
    "$@" >"$TMP/out" 2>"$TMP/err" <"${STDIN_FILE:-/dev/null}" || rc=$?
    local why=""
    [[ $rc == "$want_rc" ]] || why+=" exit $rc (want $want_rc)"
    [[ -z $out_re ]] || grep -Eq -- "$out_re" "$TMP/out" || why+=" stdout lacks /$out_re/"
    [[ -z $err_re ]] || grep -Eq -- "$err_re" "$TMP/err" || why+=" stderr lacks /$err_re/"
    if [[ -z $why ]]; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL $name:$why"
        sed 's/^/  stdout: /' "$TMP/out"
        sed 's/^/  stderr: /' "$TMP/err"
    fi
}

# Same, with the given text on stdin (a file, so froth sees no terminal) instead of /dev/null.
check_stdin() {
    printf '%s\n' "$1" >"$TMP/stdin"
    shift
    STDIN_FILE=$TMP/stdin check "$@"
}

cat >"$TMP/args.lua" <<'EOF'
print("arg0=" .. arg[0], "arg1=" .. arg[1], "n=" .. #arg, "dots=" .. table.concat({...}, ","))
EOF
cat >"$TMP/fails.lua" <<'EOF'
local function inner() error("deliberate failure") end
inner()
EOF
printf 'os.exit(7)\n' >"$TMP/exit7.lua"
printf 'print(40 + 2)\n' >"$TMP/chunk.lua"

check "-e prints" 0 '^2$' '' -- "$FROTH" -e 'print(1+1)'
check "-e repeats in order" 0 '^ab$' '' -- "$FROTH" -e 'x = "a"' -e 'print(x .. "b")'
check "-e then script" 0 'arg1=p' '' -- "$FROTH" -e 'y = 1' "$TMP/args.lua" p
check "--version" 0 '^froth [0-9]+\.[0-9]+\.[0-9]+$' '' -- "$FROTH" --version
check "-v" 0 '^froth [0-9]+\.[0-9]+\.[0-9]+$' '' -- "$FROTH" -v
check "--help" 0 'docs/lua_api.md' '' -- "$FROTH" --help
check "--help lists -e" 0 '-e stat' '' -- "$FROTH" --help
check "froth global" 0 '^[0-9]+\.[0-9]+\.[0-9]+$' '' -- "$FROTH" -e 'print(froth.version)'
check "require froth" 0 '^true$' '' -- "$FROTH" -e 'print(require("froth") == froth)'
check "help defined" 0 '^function$' '' -- "$FROTH" -e 'print(type(help))'
check "script args" 0 "arg0=$TMP/args.lua	arg1=a	n=2	dots=a,b" '' -- \
    "$FROTH" "$TMP/args.lua" a b
check "negative arg: interpreter, options" 0 "^$FROTH	-e\$" '' -- \
    "$FROTH" -e 'print(arg[-3], arg[-2])' "$TMP/chunk.lua"
check "script error message" 1 '' 'froth: .*fails.lua:1: deliberate failure' -- \
    "$FROTH" "$TMP/fails.lua"
check "script error traceback" 1 '' 'stack traceback' -- "$FROTH" "$TMP/fails.lua"
check "-e error" 1 '' '^froth: \(command line\):1: boom' -- "$FROTH" -e 'error("boom")'
check "syntax error" 1 '' 'froth: .*near' -- "$FROTH" -e 'x = = 1'
check "missing script" 1 '' 'cannot open' -- "$FROTH" "$TMP/no_such_file.lua"
check "os.exit" 7 '' '' -- "$FROTH" "$TMP/exit7.lua"
check "script runs fine" 0 '^42$' '' -- "$FROTH" "$TMP/chunk.lua"
check_stdin 'print(40+2)' "piped stdin" 0 '^42$' '' -- "$FROTH"
check_stdin 'print(40+2)' "froth -" 0 '^42$' '' -- "$FROTH" -
check_stdin 'print(...)' "froth - args" 0 '^x	y$' '' -- "$FROTH" - x y
check_stdin 'error("piped")' "piped error" 1 '' 'piped' -- "$FROTH"
check "unknown option" 1 '' "unrecognized option '-z'" -- "$FROTH" -z
check "unknown long option" 1 '' 'usage: ' -- "$FROTH" --frobnicate
check "-e without argument" 1 '' 'needs argument' -- "$FROTH" -e
check "-- ends options" 0 '^42$' '' -- "$FROTH" -- "$TMP/chunk.lua"
check "-l module" 0 '^aa$' '' -- "$FROTH" -l string -e 'print(string.rep("a", 2))'
check "no banner without a terminal" 0 '^42$' '' -- "$FROTH" "$TMP/chunk.lua"
[[ $(grep -c . "$TMP/out") == 1 ]] || { failed=$((failed + 1)); echo "FAIL banner printed"; }

# Runs froth on a script in the background, sends it SIGINT after 2 s and waits: stdout and
# stderr in $TMP/out and $TMP/err, the exit code in rc, the seconds the script took to end after
# the interrupt from $start.
interrupt_after_2s() {
    "$FROTH" "$1" >"$TMP/out" 2>"$TMP/err" &
    local pid=$!
    sleep 2
    kill -INT "$pid"
    start=$SECONDS
    wait "$pid"
    rc=$?
}

# Ctrl-C during gmsh meshing is served at once (the mesh runs in a child process that is
# killed), the script goes on, and no meshing process is left behind. The mesh asked for takes
# about 90 s on one core; the check allows 20 s from the interrupt.
if "$FROTH" -e 'os.exit(froth.has("gmsh") and 0 or 1)'; then
    cat >"$TMP/mesh.lua" <<'LUA'
local ok, err = pcall(froth.double_bubble, {h = 0.006})
print(ok, err)
print(froth.double_bubble{h = 0.3}:info().bodies)
LUA
    interrupt_after_2s "$TMP/mesh.lua"
    if [[ $rc != 0 ]] || (( SECONDS - start > 20 )) ||
        ! grep -q 'double_bubble: interrupted (Ctrl-C) while gmsh was meshing; nothing was built' "$TMP/out" ||
        ! grep -q '^2$' "$TMP/out" || pgrep -f "$TMP/mesh.lua" >/dev/null; then
        failed=$((failed + 1))
        echo "FAIL Ctrl-C during meshing: rc $rc after $((SECONDS - start)) s"
        sed 's/^/  stdout: /' "$TMP/out"
    else
        passed=$((passed + 1))
    fi
fi

# Ctrl-C during Lloyd's relaxation (thousands of Voronoi diagrams) stops it between steps as a
# Lua error naming how far it got, and the script goes on (needs CGAL).
if "$FROTH" -e 'os.exit(froth.has("cgal") and 0 or 1)'; then
    cat >"$TMP/lloyd.lua" <<'LUA'
local sites = {}
math.randomseed(2)
for i = 1, 300 do sites[i] = {7 * math.random(), 7 * math.random(), 7 * math.random()} end
print(pcall(froth.voronoi_cells, {sites = sites, period = {{7, 0, 0}, {0, 7, 0}, {0, 0, 7}}, lloyd = 10000}))
print(#froth.voronoi_cells{sites = {{0, 0, 0}, {1, 1, 1}}, period = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}}.volumes)
LUA
    interrupt_after_2s "$TMP/lloyd.lua"
    if [[ $rc != 0 ]] || (( SECONDS - start > 20 )) ||
        ! grep -q 'foam: interrupted (Ctrl-C) after [0-9]* of 10000 Lloyd steps; nothing was built' "$TMP/out" ||
        ! grep -q '^2$' "$TMP/out"; then
        failed=$((failed + 1))
        echo "FAIL Ctrl-C during Lloyd's relaxation: rc $rc"
        sed 's/^/  stdout: /' "$TMP/out"
    else
        passed=$((passed + 1))
    fi
fi

# Ctrl-C during an evolution stops it between steps, says where on stderr, and the script goes
# on with stop_reason "interrupted" (no gmsh needed).
cat >"$TMP/evolve.lua" <<'LUA'
local c = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
c:refine(); c:refine(); c:refine()
local r = c:evolve{flow = "sd", tau = 1e-4, steps = 1000000}
print(r.stop_reason, r.steps > 0, r.t == c:time())
LUA
interrupt_after_2s "$TMP/evolve.lua"
if [[ $rc != 0 ]] || ! grep -q '^interrupted	true	true$' "$TMP/out" ||
    ! grep -q '^evolve: interrupted (Ctrl-C) at step [1-9][0-9]*, t = .*; the cluster keeps the state of that step$' "$TMP/err"; then
    failed=$((failed + 1))
    echo "FAIL Ctrl-C during evolve: rc $rc"
    sed 's/^/  stdout: /' "$TMP/out"
    sed 's/^/  stderr: /' "$TMP/err"
else
    passed=$((passed + 1))
fi

echo "$passed passed, $failed failed"
[[ $failed == 0 ]]
