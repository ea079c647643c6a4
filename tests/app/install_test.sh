#!/usr/bin/env bash
# cmake --install gives a relocatable froth: install into a temporary prefix, move the prefix,
# and run the moved froth from another folder with no FROTH_* variables and no source tree on
# its paths: its Lua library (the named clusters), its gmsh plugin, datafiles, docs and man page
# must all come from the moved prefix.
# Usage: tests/app/install_test.sh BUILD_DIR      Exit status 0 iff every check passes.
set -u
BUILD=${1:?usage: $0 build-dir}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failed=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

cmake --install "$BUILD" --prefix "$TMP/first" >"$TMP/install.log" 2>&1 || { cat "$TMP/install.log"; exit 1; }
mv "$TMP/first" "$TMP/moved"
P=$TMP/moved
[[ -x $P/bin/froth ]] || fail "no bin/froth"
[[ -f $P/share/man/man1/froth.1 ]] || fail "no man page"
[[ -f $P/share/doc/froth/lua_api.md ]] || fail "no docs"
[[ -n $(ls "$P"/share/froth/datafiles/*.lua 2>/dev/null) ]] || fail "no datafiles"

mkdir "$TMP/elsewhere"
cd "$TMP/elsewhere" || exit 1
out=$(env -u FROTH_LUA_DIR -u FROTH_GMSH_PLUGIN -u FROTH_DATAFILES "$P/bin/froth" -e '
  local where = package.searchpath("froth.test", package.path)
  print(where)
  print(type(froth.box_cells))
  if froth.has("gmsh") then print(froth.torus_bubble ~= nil, froth.double_bubble{h = 0.3}:info().bodies) end
  print("manual " .. tostring(froth._manual))
  help("evolve")
' 2>&1)
rc=$?
[[ $rc == 0 ]] || fail "moved froth failed (rc $rc): $out"
grep -q "^$P/share/froth/lua/froth/test.lua$" <<<"$out" || fail "Lua library not from the prefix: $out"
grep -q "^function$" <<<"$out" || fail "froth.box_cells missing: $out"
grep -q "^manual $P/share/doc/froth/lua_api.md$" <<<"$out" || fail "manual not from the prefix: $out"
grep -q "^### c:evolve{" <<<"$out" || fail "help('evolve') from the moved prefix: $out"
if "$P/bin/froth" -e 'os.exit(froth.has("gmsh") and 0 or 1)'; then
  grep -q "^true	2$" <<<"$out" || fail "gmsh builders from the prefix: $out"
  [[ -f $(ls "$P"/lib*/froth/libfroth_gmsh.so "$P"/lib/*/froth/libfroth_gmsh.so 2>/dev/null | head -1) ]] ||
    fail "no libfroth_gmsh.so under the prefix"
fi
# a datafile from the prefix runs (smoke mode: a few steps)
env -u FROTH_LUA_DIR FROTH_SMOKE=1 "$P/bin/froth" "$P/share/froth/datafiles/sphere_mcf.lua" >"$TMP/df.log" 2>&1 ||
  fail "datafile from the prefix: $(tail -3 "$TMP/df.log")"

echo "install test: $failed failed"
[[ $failed == 0 ]]
