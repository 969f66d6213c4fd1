#!/usr/bin/env bash
# The repository stands alone: no tracked text file names a folder outside it (../shared,
# the analytic reference by its old outside name) or an absolute path of a development
# machine (/home/..., /root/..., /work/..., /tmp/..., /var/...), so a fresh clone finds
# everything it refers to, and committed results carry no machine's paths.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_repo"
pattern='(\.\./shared/|ANALYTIC\.md|(^|[ "(:])/(home|root|work|tmp|var)/[A-Za-z])'
if git rev-parse --git-dir > /dev/null 2>&1; then
    hits=$(git grep -InE "$pattern" -- . ':!tests/test_repo.sh' | head -20)
else
    hits=$(grep -rInE "$pattern" --exclude-dir='build*' --exclude-dir=.git \
           --exclude=test_repo.sh . | head -20)
fi
[ -z "$hits" ] || fail "files name paths outside the repository:
$hits"
finish test_repo
