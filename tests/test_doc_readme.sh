#!/usr/bin/env bash
# test_doc_readme.sh - README.md's commands run as written (tests/doc_commands.sh).
exec bash "$(dirname "$0")/doc_commands.sh" README.md test_doc_readme
