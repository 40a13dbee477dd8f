#!/bin/bash
# Run in a folder holding refs.sh, points.py, blank.py and bigwin.so (see refs.sh), with Xvfb on :97.
# rec_hack.sh HACK [ARGS...] -> corpus/xss-HACK.*; prints a status line to status.txt
H=$1; shift
export DISPLAY=:97 LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=1
OUT=${OUT:-../conformance/traces/corpus}
N=xss-$H
rm -f raw-$H.trace
timeout -s INT ${SECS:-4} apitrace trace --api egl -o raw-$H.trace /usr/libexec/xscreensaver/$H -window -geometry 320x240 "$@" >/dev/null 2>&1
[ -s raw-$H.trace ] || { echo "$N notrace" >> status.txt; exit; }
apitrace dump --color=never raw-$H.trace > raw-$H.txt 2>/dev/null
if grep -qE '^[0-9]+ gl(CreateShader|ShaderSource|UseProgram|CompileShader|CreateProgram)' raw-$H.txt; then
  echo "$N shaders" >> status.txt; rm -f raw-$H.trace raw-$H.txt; exit; fi
S=$(grep -cE '^[0-9]+ eglSwapBuffers' raw-$H.txt)
[ $S -ge 6 ] || { echo "$N swaps=$S" >> status.txt; exit; }
for F in 19 11 7 5; do
  [ $F -ge $S ] && continue
  apitrace trim --frames=0-$F -o $N.trace raw-$H.trace >/dev/null 2>&1
  sz=$(stat -c %s $N.trace); [ $sz -lt 1200000 ] && break
done
[ $sz -lt 2000000 ] || { echo "$N big=$sz" >> status.txt; exit; }
OUT=$OUT DISPLAY=:97 bash refs.sh $N swap >/dev/null 2>&1 || { echo "$N refsfail" >> status.txt; rm -rf $OUT/$N.*; exit; }
r=$(/usr/bin/python3 blank.py $OUT/$N.frames 2>&1 | tail -1)
case "$r" in ok*) echo "$N ok frames=0-$F size=$sz args=$* $r" >> status.txt;;
  *) echo "$N dropped $r" >> status.txt; rm -rf $OUT/$N.trace $OUT/$N.frames;; esac
rm -f raw-$H.txt
