#!/usr/bin/env bash
# test_doc_tutorial.sh - docs/tutorial.md's files are as shown and its commands run as
# written (tests/doc_commands.sh).
exec bash "$(dirname "$0")/doc_commands.sh" docs/tutorial.md test_doc_tutorial
