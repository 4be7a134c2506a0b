# Draws Aula's Autopark street (worlds/autopark.world) as docs/images/autopark_street.svg, world metres
# to pixels; the Autopark page shows it. Run: python3 docs/exercises/draw_autopark_street.py (from the checkout).
S = 26.0                      # px per metre
X0, X1, Y0, Y1 = -18.0, 17.5, -5.6, 6.0
W, H = (X1 - X0) * S, (Y1 - Y0) * S + 40
def px(x): return (x - X0) * S
def py(y): return (Y1 - y) * S
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W:.0f}" height="{H:.0f}" viewBox="0 0 {W:.0f} {H:.0f}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W:.0f}" height="{H:.0f}" fill="white"/>',
       f'<rect x="0" y="{py(5):.1f}" width="{W:.0f}" height="{(5 + 4.25) * S:.1f}" fill="#eeeeee"/>']
def rect(cx, cy, l, w, fill, stroke="black", dash=None, yaw=0):
    d = f' stroke-dasharray="{dash}"' if dash else ''
    out.append(f'<rect x="{px(cx - l / 2):.1f}" y="{py(cy + w / 2):.1f}" width="{l * S:.1f}" height="{w * S:.1f}" fill="{fill}" stroke="{stroke}"{d}/>')
def text(x, y, s, anchor="middle", color="black", size=12):
    out.append(f'<text x="{px(x):.1f}" y="{py(y):.1f}" text-anchor="{anchor}" fill="{color}" font-size="{size}">{s}</text>')
def line(x0, y0, x1, y1, color="black", width=1, dash=None, marker=False):
    d = f' stroke-dasharray="{dash}"' if dash else ''
    m = ' marker-end="url(#arrow)"' if marker else ''
    out.append(f'<line x1="{px(x0):.1f}" y1="{py(y0):.1f}" x2="{px(x1):.1f}" y2="{py(y1):.1f}" stroke="{color}" stroke-width="{width}"{d}{m}/>')
out.append('<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="context-stroke"/></marker></defs>')
# curbs
out.append(f'<rect x="0" y="{py(-4.25):.1f}" width="{W:.0f}" height="{(5.6 - 4.25) * S:.1f}" fill="#9e9e9e"/>')
out.append(f'<rect x="0" y="{py(6.0):.1f}" width="{W:.0f}" height="{1.0 * S:.1f}" fill="#9e9e9e"/>')
text(X0 + 0.3, -4.95, "curb: its face at y = -4.25 m", "start")
text(X0 + 0.3, 5.35, "far curb: its face at y = +5 m", "start")
# slot
out.append(f'<rect x="{px(2.75):.1f}" y="{py(-2.1):.1f}" width="{9 * S:.1f}" height="{(4.25 - 2.1) * S:.1f}" fill="#c8e6c9"/>')
rect(7.25, -3, 4, 2, "none", "#2e7d32", "6,4")
text(7.25, -3.15, "ideal: (7.25, -3), yaw 0", color="#2e7d32", size=11)
line(2.75, -1.35, 11.75, -1.35, "#2e7d32", marker=True)
line(11.75, -1.35, 2.75, -1.35, "#2e7d32", marker=True)
text(7.25, -1.15, "slot: x = 2.75 .. 11.75 m (9 m)", color="#2e7d32")
# parked cars
for x in (-7, 0.5, 14):
    rect(x, -3, 4.5, 1.8, "#90a4ae")
    text(x, -3.1, f"x = {x:g}", size=11)
text(-7, -2.0 + 0.35, "parked cars 4.5 x 1.8 m, centred at y = -3", size=11)
# the car at its start
cx, cy = -7, 2.5
rect(cx, cy, 4, 2, "#fff176")
text(cx, cy + 1.25, "car 4 x 2 m, start (-7, 2.5), yaw 0", size=11)
for (mx, my, yaw, name, anchor) in ((2.0, 0, 0, "front (2.0, 0), looking ahead", "start"),
                                    (-1.9, 0, 180, "rear (-1.9, 0), looking behind", "end"),
                                    (0.3, -1.0, -90, "right (0.3, -1.0), looking right", "start")):
    import math
    lx, ly = cx + mx, cy + my
    out.append(f'<circle cx="{px(lx):.1f}" cy="{py(ly):.1f}" r="4" fill="#d32f2f"/>')
    a = math.radians(yaw)
    r = 1.6
    # the 180-degree fan: from the laser's right to its left
    ax0, ay0 = lx + r * math.cos(a - math.pi / 2), ly + r * math.sin(a - math.pi / 2)
    ax1, ay1 = lx + r * math.cos(a + math.pi / 2), ly + r * math.sin(a + math.pi / 2)
    out.append(f'<path d="M{px(ax0):.1f},{py(ay0):.1f} A{r * S:.1f},{r * S:.1f} 0 0 0 {px(ax1):.1f},{py(ay1):.1f}" fill="none" stroke="#d32f2f" stroke-dasharray="3,3"/>')
    line(lx, ly, lx + r * math.cos(a), ly + r * math.sin(a), "#d32f2f", 1.5, marker=True)
    tx, ty = lx + (r + 0.2) * math.cos(a), ly + (r + 0.2) * math.sin(a)
    if yaw == -90:
        tx, ty = lx + 0.3, ly - 1.3
    else:
        ty = ly + 0.35
    text(tx, ty - 0.1, name, anchor, "#d32f2f", 11)
# axes
line(-17.5, 3.8, -15.5, 3.8, marker=True); text(-15.2, 3.7, "x", "start")
line(-17.5, 3.8, -17.5, 4.8, marker=True)
text(-17.6, 4.3, "y", "end")
text(X0 + 0.3, Y0 - 0.9, "Aula's Autopark street (worlds/autopark.world), world metres; each laser: 180 beams over 180 degrees, 0.08-10 m, 20 Hz", "start", size=11)
out.append('</svg>')
open(__import__('os').path.join(__import__('os').path.dirname(__file__), '..', 'images', 'autopark_street.svg'), 'w').write("\n".join(out) + "\n")
