# Sourced by the tests that signal a running hexgait.
#
# A job started with & in a non-interactive shell inherits SIGINT as ignored, so a signal sent
# before the program has installed its handlers is lost (or, for SIGTERM, kills it without its
# clean-up): on a loaded machine, or under the sanitizers, start-up can take over a second.
# wait_until_catching PID: until PID catches both SIGINT and SIGTERM (at most 60 s); fails if
# PID has gone or never installs them.
wait_until_catching() {
  local mask
  for _ in $(seq 3000); do
    mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$1/status" 2>/dev/null || true)
    [ -n "$mask" ] || return 1
    (((16#$mask & 0x4002) == 0x4002)) && return 0  # bit 1: SIGINT (2), bit 14: SIGTERM (15)
    sleep 0.02
  done
  return 1
}
