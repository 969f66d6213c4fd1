#!/usr/bin/env bash
# `ssgraph view` survives requests that once crashed it, answering an error and serving on:
# - a camera whose view vector overflows float (position 2e38, target -2e38: each finite),
#   and one with an infinite or NaN coordinate: 400, and a good camera still runs;
# - frame 2147483647 (the last int) and then runs: each answers, none overflows a frame
#   number (no sanitizer report in the server's output), and frame 0 runs afterwards.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_view_hostile"
source "$(dirname "$0")/view_lib.sh"
ROOT=$(pwd)
view_start_ao 48x27
alive() {
    kill -0 $pid 2>/dev/null || { fail "the server died after $1: $(tail -5 "$TMP/view.log")"; return 1; }
    expect_code 200 -H "$H" "$B/api/state"
}

# --- cameras that cannot be
for cam in "position=2e38,2e38,2e38&target=-2e38,-2e38,-2e38" \
    "position=0,1,3.5&target=inf,0,0" "position=nan,1,3.5&target=0,1,0" \
    "position=1e30,1,3.5&target=-1e30,1,0"; do
    expect_code 400 -H "$H" -d "$cam&up=0,1,0&fov=40&preview=0" "$B/api/camera"
    alive "POST /api/camera $cam" || finish test_view_hostile
    expect_code 400 -H "$H" -d "$cam&up=0,1,0&fov=40&preview=1" "$B/api/camera"
    alive "POST /api/camera $cam (preview)" || finish test_view_hostile
done
expect_code 200 -H "$H" -d "position=0,1,3.5&target=0,1,0&up=0,1,0&fov=40&preview=0" "$B/api/camera"

# --- the last frame number, then runs that would follow it
for req in "frame=2147483647 /api/frame" "ref.rays=5 /api/set" "frame=2147483647 /api/frame" \
    "ref.rays=6 /api/set"; do
    got=$(code -H "$H" -d "${req% *}" "$B${req#* }")
    case $got in
    200 | 400) ;;
    *) fail "POST ${req#* } ${req% *} answered $got: $(head -c 300 "$TMP/body")" ;;
    esac
    alive "POST ${req#* } ${req% *}" || finish test_view_hostile
done
expect_code 200 -H "$H" -d "frame=0" "$B/api/frame"
grep -q "runtime error" "$TMP/view.log" && fail "a sanitizer report: $(grep -m3 "runtime error" "$TMP/view.log")"

view_stop_within 10000 TERM
finish test_view_hostile
