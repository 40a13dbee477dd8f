# features.py DUMP.txt: a one-line summary of the GL features a capture exercises.
import re, sys
caps, prims, blend, fog, texenv, texgen, fmts, also = [], [], [], [], [], [], [], []
def add(l, v):
    if v not in l: l.append(v)
calls = 0
for line in open(sys.argv[1], errors='replace'):
    m = re.match(r'^(\d+) (\w+)\((.*)\)', line)
    if not m: continue
    calls += 1
    f, a = m.group(2), m.group(3)
    g = lambda: re.findall(r'GL_(\w+)', a)
    if f == 'glEnable':
        for e in g(): add(caps, e)
    elif f == 'glBegin':
        for e in g(): add(prims, e)
    elif f in ('glDrawArrays', 'glDrawElements', 'glDrawRangeElements', 'glMultiDrawArrays'):
        add(also, 'vertex arrays')
        for e in g()[:1]: add(prims, e)
    elif f == 'glBlendFunc':
        e = g();
        if len(e) >= 2: add(blend, e[0] + '/' + e[1])
    elif f.startswith('glFog') and 'GL_FOG_MODE' in a:
        for e in g()[1:]: add(fog, e)
    elif f.startswith('glTexEnv') and 'GL_TEXTURE_ENV_MODE' in a:
        for e in g()[2:]: add(texenv, e)
    elif f.startswith('glTexGen') and 'GL_TEXTURE_GEN_MODE' in a:
        for e in g()[2:]: add(texgen, e)
    elif f in ('glTexImage1D', 'glTexImage2D', 'glTexImage3D'):
        m2 = re.search(r'internalformat = (\w+)', a)
        if m2: add(fmts, m2.group(1).replace('GL_', ''))
    else:
        k = {'glNewList': 'display lists', 'glPolygonMode': 'polygon mode', 'glLineStipple': 'line stipple',
             'glPolygonStipple': 'polygon stipple', 'glLogicOp': 'logic op', 'glStencilOp': 'stencil ops',
             'glStencilFunc': 'stencil func', 'glBitmap': 'glBitmap', 'glDrawPixels': 'glDrawPixels',
             'glCopyPixels': 'glCopyPixels', 'glRenderMode': 'glRenderMode', 'glClipPlane': 'clip planes',
             'glAccum': 'accumulation', 'glEvalMesh2': 'evaluators', 'glEvalMesh1': 'evaluators',
             'glMap2f': 'evaluators', 'glCopyTexImage2D': 'glCopyTexImage', 'glCopyTexSubImage2D': 'glCopyTexSubImage',
             'glTexSubImage2D': 'glTexSubImage', 'glMaterialfv': 'materials', 'glColorMaterial': 'color material',
             'glLightModelfv': 'light model', 'glLightModeli': 'light model', 'glPolygonOffset': 'polygon offset',
             'glAlphaFunc': 'alpha func', 'glDepthFunc': 'depth func', 'glDepthRange': 'depth range',
             'glRasterPos2f': 'raster pos', 'glRasterPos3f': 'raster pos', 'glRasterPos2i': 'raster pos',
             'glWindowPos2i': 'window pos', 'glPointSize': 'point size', 'glLineWidth': 'line width',
             'glSecondaryColor3f': 'secondary colour', 'glFogCoordf': 'fog coordinate', 'glMultiTexCoord2f': 'multitexture',
             'glActiveTexture': 'multitexture', 'glBindBuffer': 'buffer objects', 'glScissor': 'scissor',
             'glShadeModel': 'shade model', 'glColorMask': 'colour mask', 'glDrawBuffer': 'draw buffer',
             'glReadPixels': 'glReadPixels', 'glPixelZoom': 'pixel zoom', 'glPixelTransferf': 'pixel transfer',
             'glFrontFace': 'front face', 'glCullFace': 'cull face', 'glEdgeFlag': 'edge flags',
             'glGenerateMipmap': 'mipmaps', 'gluBuild2DMipmaps': 'mipmaps', 'glPushAttrib': 'attribute stack'}.get(f)
        if k: add(also, k)
        if f == 'glTexParameteri' and 'GL_GENERATE_MIPMAP' in a: add(also, 'mipmaps')
out = []
for n, l in (('caps', caps), ('prims', prims), ('blend', blend), ('fog', fog), ('texenv', texenv),
             ('texgen', texgen), ('tex formats', fmts), ('also', also)):
    if l: out.append(n + ': ' + ','.join(l[:12]) + (' ...' if len(l) > 12 else ''))
print('; '.join(out))
