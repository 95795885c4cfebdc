#!/bin/sh
# Runs a command under a resource limit of the shell's ulimit (-v: address space, -d: data,
# in kibibytes), so that checks of the available memory answer alike on every machine.
# Usage: with_ulimit.sh OPTION KIB COMMAND [ARGS...]
option=$1
limit=$2
shift 2
ulimit "$option" "$limit" && exec "$@"
