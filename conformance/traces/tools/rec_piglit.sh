#!/bin/bash
# Run in a folder holding refs.sh, points.py, blank.py and bigwin.so (see refs.sh), with Xvfb on :97.
# rec_piglit.sh TEST [ARGS...] -> corpus/piglit-TEST[-ARGS].*
T=$1; shift
export DISPLAY=:97 LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=1 PIGLIT_PLATFORM=glx
OUT=${OUT:-../conformance/traces/corpus}
N=piglit-$T; [ $# -gt 0 ] && N="$N-$(echo "$*" | tr ' ' '-')"
rm -f $N.trace
res=$(timeout 20 apitrace trace --api gl -o $N.trace /usr/lib/x86_64-linux-gnu/piglit/bin/$T "$@" -auto 2>&1 | grep -o '"result": "[a-z]*"' | tail -1 | cut -d'"' -f4)
[ -s $N.trace ] || { echo "$N notrace" >> pstatus.txt; exit; }
apitrace dump --color=never $N.trace > $N.txt 2>/dev/null
if grep -qE '^[0-9]+ gl(CreateShader|ShaderSource|UseProgram|CompileShader|CreateProgram)' $N.txt; then
  echo "$N shaders" >> pstatus.txt; rm -f $N.trace $N.txt; exit; fi
sz=$(stat -c %s $N.trace)
[ $sz -lt 2000000 ] || { echo "$N big=$sz" >> pstatus.txt; exit; }
OUT=$OUT DISPLAY=:97 bash refs.sh $N piglit >/dev/null 2>&1 || { echo "$N refsfail" >> pstatus.txt; rm -rf $OUT/$N.*; exit; }
r=$(/usr/bin/python3 blank.py $OUT/$N.frames 2>&1 | tail -1)
case "$r" in ok*) echo "$N ok verdict=$res size=$sz args=$* $r" >> pstatus.txt;;
  *) echo "$N dropped verdict=$res $r" >> pstatus.txt; rm -rf $OUT/$N.trace $OUT/$N.frames;; esac
