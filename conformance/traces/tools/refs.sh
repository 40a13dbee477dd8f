#!/bin/bash
# Writes NAME.trace and NAME.frames/ (frames.tsv, llvmpipe PNGs, softpipe/ PNGs) into $OUT.
# Run in the folder holding NAME.trace, points.py and bigwin.so (gcc -shared -fPIC -o bigwin.so bigwin.c -ldl).
# refs.sh NAME KIND(piglit|swap) -> conformance/traces/NAME.trace + NAME.frames/
# CALLS=N,M,... picks the snapshot calls instead of points.py / the last three swaps.
set -e
export DISPLAY=${DISPLAY:-:99} LIBGL_ALWAYS_SOFTWARE=1
NAME=$1; KIND=$2; OUT=${OUT:-../conformance/traces}
mkdir -p $OUT
T=$NAME.trace
apitrace dump --color=never $T > $NAME.txt
if [ $KIND = piglit ]; then
  CALLS=${CALLS:-$(python3 points.py $NAME.txt)}; PRE="LD_PRELOAD=$PWD/bigwin.so"
else
  CALLS=${CALLS:-$(grep -E '^[0-9]+ (egl|glX)SwapBuffers' $NAME.txt | tail -3 | cut -d' ' -f1 | paste -sd,)}; PRE=""
fi
rm -rf snap-$NAME snap-$NAME-sp; mkdir snap-$NAME snap-$NAME-sp
env $PRE apitrace replay -S $CALLS -s snap-$NAME/ $T > /dev/null 2>&1
env $PRE GALLIUM_DRIVER=softpipe apitrace replay -S $CALLS -s snap-$NAME-sp/ $T > /dev/null 2>&1
cp $T $OUT/$NAME.trace
D=$OUT/$NAME.frames; rm -rf $D; mkdir -p $D/softpipe
printf 'file\tframe_index\tcall_no\tsnapshot_of\n' > $D/frames.tsv
for c in ${CALLS//,/ }; do
  src=$(printf '%010d.png' $c)
  line=$(grep -E "^$c " $NAME.txt | head -1); fn=$(echo "$line" | sed -E 's/^[0-9]+ ([A-Za-z0-9_]+).*/\1/')
  if [ $KIND = piglit ]; then
    f=$(printf 'call-%010d.png' $c); idx=""
  else
    idx=$(grep -E '^[0-9]+ (egl|glX)SwapBuffers' $NAME.txt | awk -v c=$c '{ if ($1+0 == c+0) print NR-1 }')
    f=$(printf 'frame-%04d.png' $idx)
  fi
  cp snap-$NAME/$src $D/$f; cp snap-$NAME-sp/$src $D/softpipe/$f
  printf '%s\t%s\t%s\t%s\n' $f "$idx" $c $fn >> $D/frames.tsv
done
cat $D/frames.tsv; du -sh $OUT/$NAME.trace $D
