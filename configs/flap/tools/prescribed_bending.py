#!/usr/bin/env python3
"""Prescribe a bending motion of the flap (mesh-motion check, no compiled code).

Run inside a COPY of configs/flap/fluid-openfoam after blockMesh.  It writes
constant/boundaryData/flap/{points,<t>/pointDisplacement} and switches the
flap entry of 0/pointDisplacement to timeVaryingMappedFixedValue (mapMethod
nearest, the data points are the patch points themselves).  Shape: cantilever
(Euler-Bernoulli) with tip deflection A(t), linear in time between the given
instants:  dx = A (3y^2 - y^3)/2,  dy = -x A (6y - 3y^2)/2  (section rotation).

usage: prescribed_bending.py ["t0:A0 t1:A1 ..."]   default "0:0 0.5:0.2 1:-0.1"
"""
import os
import re
import sys


def foam_list(path):
    """Body of the (single) list in an ascii OpenFOAM file."""
    txt = open(path).read()
    txt = txt[txt.index('FoamFile'):]
    txt = txt[txt.index('}') + 1:]
    m = re.search(r'^\s*(\d+)\s*\(', txt, re.M)
    return txt[m.end():txt.rindex(')')]


def main():
    spec = sys.argv[1] if len(sys.argv) > 1 else "0:0 0.5:0.2 1:-0.1"
    pts = [tuple(map(float, p.split())) for p in
           re.findall(r'\(([^()]*)\)', foam_list('constant/polyMesh/points'))]
    faces = [list(map(int, f.split())) for f in
             re.findall(r'\d+\s*\(([^()]*)\)', foam_list('constant/polyMesh/faces'))]
    bnd = open('constant/polyMesh/boundary').read()
    m = re.search(r'\bflap\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);', bnd)
    n, start = int(m.group(1)), int(m.group(2))
    P = [pts[i] for i in sorted({i for f in faces[start:start + n] for i in f})]

    d = 'constant/boundaryData/flap'
    os.makedirs(d, exist_ok=True)
    with open(d + '/points', 'w') as f:
        f.write('%d\n(\n' % len(P))
        f.writelines('(%.10g %.10g %.10g)\n' % p for p in P)
        f.write(')\n')
    for item in spec.split():
        t, A = (float(s) for s in item.split(':'))
        os.makedirs('%s/%g' % (d, t), exist_ok=True)
        with open('%s/%g/pointDisplacement' % (d, t), 'w') as f:
            f.write('%d\n(\n' % len(P))
            for x, y, _ in P:
                f.write('(%.10g %.10g 0)\n' % (A * (3*y*y - y**3) / 2,
                                               -x * A * (6*y - 3*y*y) / 2))
            f.write(')\n')

    pd = open('0/pointDisplacement').read()
    pd = re.sub(r'\bflap\s*\{[^}]*\}', '''flap
    {
        type            timeVaryingMappedFixedValue;
        mapMethod       nearest;
        offset          (0 0 0);
        setAverage      false;
        value           uniform (0 0 0);
    }''', pd, count=1)
    open('0/pointDisplacement', 'w').write(pd)
    print('flap patch: %d faces, %d points; tip deflection table: %s'
          % (n, len(P), spec))


if __name__ == '__main__':
    main()
