#!/usr/bin/env python3
# Distance vs tolerance LOD from a `globe trade --lod-sweep` trade.csv (docs/tradeoffs.md, "Tolerance vs
# distance ranges"): per standard camera, the triangles the distance multipliers need for the p95 error
# a tolerance row reaches (log-log interpolation along the distance rows' frontier), summed over the cameras.
# Tolerance rows are `tolerance` (one range per depth) and `tolerance-roughness` (ranges following the
# relief's roughness). Usage: scripts/trade_lod_compare.py DIR/trade.csv [MORE.csv ...] (rows of all files)
import csv, math, sys
rows=[r for f in sys.argv[1:] for r in csv.DictReader(open(f))]
cams=[c for c in ['orbit','100km','10km','1km','2m','path@7s','path@12s'] if any(r['camera']==c for r in rows)]
get=lambda cfg,c:[x for x in rows if x['config']==cfg and x['camera']==c][0]
cfgs=list(dict.fromkeys(r['config'] for r in rows))
lod={r['config']:r['lod'] for r in rows}  # a config's rule, from whichever cameras were swept
dist=[c for c in cfgs if lod[c]=='distance']
tol=[c for c in cfgs if lod[c].startswith('tolerance')]
def frontier(cam):
    # Distance rows that no other distance row beats on both triangles and error: a row held back by
    # the frame budget (millions of triangles, hundreds of px) is dominated and left out.
    pts=[(float(get(c,cam)['err_p95_px']),int(get(c,cam)['triangles'])) for c in dist]
    keep=[p for p in pts if not any(q!=p and q[0]<=p[0] and q[1]<=p[1] for q in pts)]
    return sorted(keep, key=lambda p:-p[0])
def distTris(cam, err):
    pts=frontier(cam)
    # frontier: error falls as triangles rise; interpolate log-log between neighbours
    best=None
    for (e1,t1),(e2,t2) in zip(pts,pts[1:]):
        if e2<=err<=e1 and e1>e2:
            f=(math.log(e1)-math.log(err))/(math.log(e1)-math.log(e2))
            return math.exp(math.log(t1)+f*(math.log(t2)-math.log(t1)))
    if err>=pts[0][0]: return min(t for e,t in pts if e>=err*0.999) if any(e>=err*0.999 for e,t in pts) else pts[0][1]
    return None  # beyond the sweep
print("| tolerance config | lod | " + " | ".join(cams) + " | sum, tolerance | sum, distance at equal p95 | fewer |")
print("| --- | --- |" + " ---: |"*(len(cams)+3))
for t in tol:
    st=sd=0; cells=[]; ok=True
    for c in cams:
        r=get(t,c); e=float(r['err_p95_px']); tt=int(r['triangles'])
        d=distTris(c,e)
        if d is None: ok=False; cells.append(f"{tt/1e3:.0f}k @ {e:.2f} px (beyond)"); continue
        st+=tt; sd+=d; cells.append(f"{tt/1e3:.0f}k vs {d/1e3:.0f}k @ {e:.2f} px")
    print(f"| {t} | {lod[t]} | "+" | ".join(cells)+(f" | {st/1e3:.0f}k | {sd/1e3:.0f}k | {100*(1-st/sd):.0f} % |" if ok else " | – | – | – |"))
