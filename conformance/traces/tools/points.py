# Snapshot points of a piglit capture: the glReadPixels calls that follow new drawing (the
# last three), or the last drawing call when nothing is read back. Input: `apitrace dump` text.
import re, sys
draw = re.compile(r'^\d+ (glBegin|glEnd|glDraw|glClear\(|glCallList|glBitmap|glCopyPixels|glRect|glMultiDraw|glArrayElement|glEvalMesh|glAccum)')
pts = []
dirty = False
last_draw = None
for line in open(sys.argv[1]):
    m = re.match(r'^(\d+) (\w+)', line)
    if not m: continue
    n, name = int(m.group(1)), m.group(2)
    if draw.match(line):
        dirty = True; last_draw = n
    elif name == 'glReadPixels' and dirty:
        pts.append(n); dirty = False
if not pts and last_draw is not None:
    pts = [last_draw]
print(','.join(map(str, pts[-3:])))
