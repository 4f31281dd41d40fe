#!/bin/sh
# Usage: signal_twice.sh SIGNAL SECONDS PROGRAM ARGS...
# Runs PROGRAM, sends it SIGNAL after SECONDS and again a tenth of a second later (GNU timeout
# sends it to the program, then to its process group: the program receives it twice; the tenth
# of a second makes sure the first has been handled when the second comes) and exits with the
# program's status.
sig="$1"; secs="$2"; shift 2
"$@" &
p=$!
sleep "$secs"
kill -s "$sig" "$p"
sleep 0.1
kill -s "$sig" "$p"
wait "$p"
