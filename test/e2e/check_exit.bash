# Sourced by the e2e scripts that run a tool and check its exit code: check <expected exit code>
# <description> <command...> runs the command with stdout in out.txt and stderr in err.txt, and sets
# fail=1 (printing the command's stderr) when the exit code is not the expected one.
check() {
  local want=$1 what=$2
  shift 2
  "$@" >out.txt 2>err.txt
  local rc=$?
  if [ "$rc" != "$want" ]; then
    echo "FAIL: $what: exit $rc, expected $want"; cat err.txt; fail=1
  fi
}
