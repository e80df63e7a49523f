#!/usr/bin/env bash
# The launcher as the README uses it (ctest launcher.*): through a symbolic link on PATH from another
# folder, --version / --help, and — as root — as another (non-root) user on this existing build:
# the run works and nothing is written into the build folder.
#   tests/launcher_check.sh SOURCE_DIR BUILD_DIR
# Exit 0 when every check passes, 1 on a failure, 77 (skipped) when not root for the user part.
set -uo pipefail
src=$1
build=$2
work=$(mktemp -d /tmp/miniaster-launcher-XXXXXX)
chmod 755 "$work"
created_user=""
cleanup() {
  rm -rf "$work"
  [ -n "$created_user" ] && userdel "$created_user" 2>/dev/null
}
trap cleanup EXIT
fail() { echo "FAILED: $*"; exit 1; }

mkdir -p "$work/bin"
ln -s "$src/miniaster" "$work/bin/miniaster"
export MINIASTER_BUILD="$build"
export PATH="$work/bin:$PATH"
cd "$work" || exit 1

out=$(miniaster --version) || fail "--version exited with $?"
version=$(sed -n 's/^project(miniaster VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
# The commit: git describe of the checkout (tools/git_version.cmake), the same in the launcher and the binary.
head=$(git -C "$src" rev-parse --short=12 HEAD)
case "$out" in "miniaster $version (commit $head"*) ;; *) fail "--version printed '$out', expected 'miniaster $version (commit $head...)'" ;; esac
case "$("$build/miniaster" --version)" in "miniaster $version (commit $head"*) ;; *) fail "the binary's --version differs: $("$build/miniaster" --version)" ;; esac
miniaster --help | grep -q "miniaster convert RESULT.rmed OUT.vtu" || fail "--help does not list convert"
miniaster nonsense >/dev/null 2>&1 && fail "an unknown command exited with 0"

miniaster run "$src/astest/fe_patch_quad4.export" --out-dir "$work/root-run" >/dev/null 2>&1 ||
  fail "run through the link exited with $?"
grep -q -- "--- DIAGNOSTIC JOB : OK" "$work/root-run/fe_patch_quad4.mess" || fail "no DIAGNOSTIC OK (link)"
echo "OK: through a link on PATH ($work/bin/miniaster), --version '$out', --help, run"

if [ "$(id -u)" -ne 0 ] || ! command -v runuser >/dev/null; then
  echo "SKIPPED: the other-user part needs root (useradd, runuser)"
  exit 77
fi
user=miniaster-check
if ! id "$user" >/dev/null 2>&1; then
  useradd --no-create-home --shell /bin/bash "$user" || fail "useradd $user"
  created_user=$user
fi
mkdir -p "$work/home" && chown "$user" "$work/home"
stamp=$(stat -c %Y "$build/.ninja_log")
as_user() { runuser -u "$user" -- env PATH="$PATH" MINIASTER_BUILD="$build" HOME="$work/home" bash -c "cd '$work/home' && $1"; }
as_user "miniaster run '$src/astest/fe_patch_quad4.export'" >"$work/user-run.txt" 2>&1 ||
  fail "run as $user exited with $? ($(tail -3 "$work/user-run.txt"))"
grep -q -- "--- DIAGNOSTIC JOB : OK" "$work/home/fe_patch_quad4.mess" || fail "no DIAGNOSTIC OK ($user)"
[ "$(stat -c %Y "$build/.ninja_log")" = "$stamp" ] || fail "the run as $user wrote into the build"
as_user "miniaster test" >"$work/user-test.txt" 2>&1 && fail "'miniaster test' as $user did not stop"
grep -q "cannot write: run them as its owner" "$work/user-test.txt" || fail "no clear message for test as $user"
echo "OK: as $user (not root, not the build's owner): run from its own folder, build untouched; test refused clearly"
