# blank.py DIR: drops pictures whose llvmpipe reference is one colour (they check nothing);
# prints "blank" when none is left or every one left is one colour save <0.2 % of the pixels,
# else "ok", the llvmpipe-vs-softpipe spread (max % of pixels off by > 8) and the size.
import sys, os
from collections import Counter
from PIL import Image
d = sys.argv[1]
lines = open(os.path.join(d, 'frames.tsv')).read().splitlines()
keep = [lines[0]]; blank = True; spread = 0.0; dims = (0, 0)
for l in lines[1:]:
    f = l.split('\t')[0]
    a = Image.open(os.path.join(d, f)).convert('RGB')
    pa = list(a.getdata())
    c = Counter(pa).most_common(1)[0][1]
    if c == len(pa):
        os.remove(os.path.join(d, f)); os.remove(os.path.join(d, 'softpipe', f)); continue
    keep.append(l); dims = a.size
    if len(pa) - c >= 20: blank = False
    b = Image.open(os.path.join(d, 'softpipe', f)).convert('RGB')
    if a.size != b.size: spread = 100.0; continue
    pb = list(b.getdata())
    off = sum(1 for x, y in zip(pa, pb) if max(abs(x[i]-y[i]) for i in range(3)) > 8)
    spread = max(spread, 100.0 * off / len(pa))
open(os.path.join(d, 'frames.tsv'), 'w').write('\n'.join(keep) + '\n')
print(('blank' if blank else 'ok'), '%.3f' % spread, '%dx%d' % dims, 'pictures=%d' % (len(keep) - 1))
