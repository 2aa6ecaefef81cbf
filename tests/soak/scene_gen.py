#!/usr/bin/env python3
"""Random legal scenes for make soak (tests/soak/soak.sh), one Lua file each.

Each scene is chapter N's (N drawn from 1 to 18) and uses only the calls of chapters 1 to N,
each value drawn from the range the reference page (docs/reference.md) allows: a random
hierarchy of spheres, boxes, meshes and smooth meshes, CSG trees and quadrics, with transforms
that may mirror and stretch, Phong materials with mirrors, glass, glossy lobes, textures and
bumps, point, area and ball lights, the pixel samplers, tone maps and lenses; from chapter 16
photon maps (gr.photons), from 17 participating media (gr.medium in closed shapes, noise and
the VDB plume, gr.fog) and from 18 the path tracer (gr.integrator) with emitting materials.
Sizes are small (24 x 18 to 48 x 36) and sample counts few, so that a scene renders in a
fraction of a second under the sanitizers.

Scene i of seed S is drawn from its own stream, random.Random(S * 1000003 + i): it is the same
whatever N is, so a failing scene can be written again alone (--first i --count 1). Each file
starts with a comment naming its chapter, --features list, --max-memory and --time-limit, which
soak.sh reads back; `index.txt` lists them, one scene a line.

usage: scene_gen.py --root REPO --out DIR --seed S --count N [--first I]
"""

import argparse
import math
import os
import random

# The chapter modules in chapter order (rt --list-features): chapter N switches on the first N.
MODULES = ["raycast", "phong", "bvh", "reflection", "refraction", "soft_shadows", "glossy",
           "adaptive_aa", "smooth_mesh", "texture", "bump", "tone_map", "dof", "csg",
           "quadrics", "photon_map", "media", "path_tracing"]


def num(x):
    """A Lua number literal holding every bit of x."""
    return repr(float(x))


def triple(v):
    return "{" + ", ".join(num(c) for c in v) + "}"


class SceneWriter:
    """Lua text for one random scene of `chapter`, drawn from `rng`."""

    def __init__(self, rng, chapter, root):
        self.rng = rng
        self.chapter = chapter
        self.root = root
        self.lines = []
        self.media = 0  # nodes holding a medium (rt allows 63)

    # ---- Drawing values ----------------------------------------------------------------
    def u(self, lo=0.0, hi=1.0):
        return self.rng.uniform(lo, hi)

    def coin(self, p=0.5):
        return self.rng.random() < p

    def direction(self, length=1.0):
        """A uniformly random direction of the given length (Marsaglia's normal trick)."""
        while True:
            v = [self.rng.gauss(0, 1) for _ in range(3)]
            n = math.sqrt(sum(c * c for c in v))
            if n > 1e-6:
                return [length * c / n for c in v]

    def colour(self, lo=0.0, hi=1.0):
        return triple([self.u(lo, hi) for _ in range(3)])

    def asset(self, name):
        return "'" + os.path.join(self.root, "scenes", name) + "'"

    def emit(self, line):
        self.lines.append(line)

    # ---- Nodes ---------------------------------------------------------------------------
    def shape(self, name):
        """A primitive: sphere, cube, nh_sphere, nh_box; a mesh from chapter 3, a smooth mesh
        from 9, a cylinder or cone from 15."""
        kinds = 8 if self.chapter >= 15 else 6 if self.chapter >= 9 else 5 if self.chapter >= 3 else 4
        kind = self.rng.randrange(kinds)
        if kind == 0:
            return f"gr.sphere('{name}')"
        if kind == 1:
            return f"gr.cube('{name}')"
        if kind == 2:
            return f"gr.nh_sphere('{name}', {triple(self.direction(self.u(0, 2)))}, {num(self.u(0.01, 2))})"
        if kind == 3:
            return f"gr.nh_box('{name}', {triple(self.direction(self.u(0, 2)))}, {num(self.u(0.01, 2))})"
        if kind == 4:
            return f"gr.mesh('{name}', {self.asset(self.rng.choice(['a4/dodeca.obj', 'a4/cubeSq.obj', 'assets/icosa.obj']))})"
        if kind == 5:
            mesh = self.rng.choice(["a4/dodeca.obj", "a4/cubeSq.obj", "assets/icosphere80.obj"])
            return (f"gr.smooth_mesh('{name}', {self.asset(mesh)}, {{normals = "
                    f"'{self.rng.choice(['file', 'computed'])}', crease = {num(self.u(0, 180))}, "
                    f"terminator = {str(self.coin()).lower()}}})")
        open_ = str(self.coin()).lower()
        if kind == 6:
            return f"gr.cylinder{{name = '{name}', open = {open_}}}"
        top = f", top_radius = {num(self.u(0.001, 1))}" if self.coin() else ""
        return f"gr.cone{{name = '{name}', open = {open_}{top}}}"

    def transforms(self, name):
        """Zero to three translations, rotations and scales (which may mirror; |f| >= 0.05)."""
        for _ in range(self.rng.randrange(4)):
            kind = self.rng.randrange(3)
            if kind == 0:
                self.emit(f"{name}:translate({num(self.u(-3, 3))}, {num(self.u(-3, 3))}, {num(self.u(-3, 3))})")
            elif kind == 1:
                self.emit(f"{name}:rotate('{self.rng.choice('xyz')}', {num(self.u(-360, 360))})")
            else:
                f = [self.u(0.05, 3) * (-1 if self.coin(0.15) else 1) for _ in range(3)]
                self.emit(f"{name}:scale({num(f[0])}, {num(f[1])}, {num(f[2])})")

    def obj(self, name, depth=0):
        """Node `name`: a shape or (chapter 14 on) a CSG tree, transformed, with a material."""
        closed = False
        if self.chapter >= 14 and depth < 2 and self.coin(0.3 if depth == 0 else 0.25):
            self.obj(name + "a", depth + 1)
            self.obj(name + "b", depth + 1)
            op = self.rng.choice(["gr.union", "gr.intersection", "gr.difference"])
            self.emit(f"local {name} = {op}({name}a, {name}b)")
            closed = True
        else:
            text = self.shape(name)
            self.emit(f"local {name} = {text}")
            closed = text.startswith(("gr.sphere", "gr.cube", "gr.mesh"))
        self.transforms(name)
        # Chapter 17: a closed shape may hold a medium, and then may go without a material
        # (the shape only bounds the medium).
        medium = depth == 0 and closed and self.chapter >= 17 and self.coin(0.3) and self.media < 60
        if medium:
            self.media += 1
            self.emit(f"{name}:set_medium({self.medium()})")
        if (depth == 0 and not (medium and self.coin())) or self.coin(0.7):
            self.material(name)

    # ---- Materials -----------------------------------------------------------------------
    def material(self, node):
        m = node + "m"
        fields = [f"kd = {self.colour()}", f"ks = {self.colour()}",
                  f"shininess = {num(self.u(0.5, 500))}"]
        if self.chapter >= 4 and self.coin():
            fields.append(f"reflect = {num(self.u())}")
        if self.chapter >= 5 and self.coin():
            fields += [f"transparency = {num(self.u())}", f"ior = {num(self.u(0.2, 4))}",
                       f"schlick = {str(self.coin()).lower()}"]
        if self.chapter >= 7 and self.coin():
            fields.append(f"glossiness = {num(self.u(0, 2))}")
        if self.chapter >= 18 and self.coin(0.3):
            fields.append(f"emission = {self.colour(0, 20)}")
        self.emit(f"local {m} = gr.material{{{', '.join(fields)}}}")
        if self.chapter >= 10 and self.coin():
            self.emit(f"{m}:set_texture('{self.rng.choice(['kd', 'ks'])}', {self.texture()})")
        if self.chapter >= 11 and self.coin():
            self.emit(f"{m}:set_bump{self.bump()}")
        self.emit(f"{node}:set_material({m})")

    def texture(self):
        """A checker or an image, in any mapping, scaled (never by 0), offset, wrapped or not."""
        if self.coin():
            source = f"checker = {{{self.colour()}, {self.colour()}}}"
        else:
            source = (f"image = {self.asset('assets/textures/globe.png')}, wrap = "
                      f"'{self.rng.choice(['repeat', 'clamp'])}', filter = "
                      f"'{self.rng.choice(['bilinear', 'nearest'])}'")

        def scale():
            return num(self.u(0.05, 20) * (-1 if self.coin(0.2) else 1))
        mapping = self.rng.choice(["surface", "planar", "spherical", "cylindrical"])
        return (f"gr.texture{{{source}, mapping = '{mapping}', scale = {{{scale()}, {scale()}}}, "
                f"offset = {{{num(self.u(-5, 5))}, {num(self.u(-5, 5))}}}}}")

    def bump(self):
        """Every pattern, at strengths from none to far past flipping the normal."""
        strength = (-1 if self.coin() else 1) * (self.u(0, 1000) if self.coin(0.2) else self.u(0, 0.2))
        kind = self.rng.randrange(4)
        if kind == 0:
            pattern = (f"pattern = 'ripples', wavelength = {num(self.u(0.01, 2))}, "
                       f"centre = {triple(self.direction(self.u(0, 2)))}")
        elif kind == 1:
            pattern = (f"pattern = 'noise', scale = {num(self.u(0.01, 2))}, octaves = "
                       f"{self.rng.randint(1, 8)}, seed = {self.rng.randint(0, 100)}")
        elif kind == 2:
            pattern = f"pattern = 'ramp', slope = {triple(self.direction(self.u(0, 3)))}"
        else:
            pattern = (f"pattern = 'image', file = {self.asset('assets/tiles-height.png')}, "
                       f"mapping = '{self.rng.choice(['surface', 'planar'])}'")
        return f"{{strength = {num(strength)}, {pattern}}}"

    # ---- Chapter 17: media ---------------------------------------------------------------
    def medium(self):
        """gr.medium{...}: grey or coloured coefficients, any g in (-1, 1), and a density that
        is a number, noise or (rarely, it is the costliest) the VDB plume."""
        def coefficient(hi):
            return self.colour(0, hi) if self.coin() else num(self.u(0, hi))
        fields = [f"sigma_a = {coefficient(2)}", f"sigma_s = {coefficient(6)}",
                  f"g = {num(self.u(-0.95, 0.95))}"]
        kind = self.rng.randrange(10)
        if kind < 4:
            fields.append(f"density = {num(self.u(0, 3))}")
        elif kind < 9:
            fields.append(f"density = {{noise = {num(self.u(0.1, 4))}, octaves = "
                          f"{self.rng.randint(1, 6)}, bias = {num(self.u(-0.5, 1))}, gain = "
                          f"{num(self.u(0, 2))}, seed = {self.rng.randint(0, 1000)}}}")
        else:
            fields.append(f"density = {{file = {self.asset('assets/plume.nvdb')}, grid = 'density'}}")
        return "gr.medium{" + ", ".join(fields) + "}"

    # ---- Lights and options --------------------------------------------------------------
    def falloff(self):
        return triple([self.u(0.05, 1), self.u(0, 0.5), self.u(0, 0.2)])

    def lights(self):
        """One to three point lights, and from chapter 6 area and ball lights."""
        out = []
        for _ in range(self.rng.randint(1, 3)):
            position = triple(self.direction(self.u(0, 8)))
            kind = self.rng.randrange(3) if self.chapter >= 6 else 0
            if kind == 0:
                out.append(f"gr.light({position}, {self.colour()}, {self.falloff()})")
            elif kind == 1:
                normal = self.direction()
                left = self.direction()
                if abs(sum(a * b for a, b in zip(normal, left))) > 0.99:
                    left = [0.0, normal[2], -normal[1]] if abs(normal[0]) < 0.9 else [normal[1], -normal[0], 0.0]
                out.append(f"gr.area_light{{position = {position}, colour = {self.colour()}, "
                           f"falloff = {self.falloff()}, size = {{{num(self.u(0, 3))}, "
                           f"{num(self.u(0, 3))}}}, normal = {triple(normal)}, left = "
                           f"{triple(left)}, samples = {self.rng.randint(1, 2)}}}")
            else:
                out.append(f"gr.ball_light{{position = {position}, colour = {self.colour()}, "
                           f"falloff = {self.falloff()}, radius = {num(self.u(0, 1.5))}, "
                           f"samples = {self.rng.randint(1, 2)}}}")
        return ", ".join(out)

    def options(self):
        """The chapters' scene-wide calls, with few samples of everything."""
        c = self.chapter
        if c >= 4:
            self.emit(f"gr.option('max_depth', {self.rng.randint(0, 4 if c >= 9 else 6)})")
        if c >= 7:
            self.emit(f"gr.option('glossy_samples', {self.rng.randint(0, 3)})")
            self.emit(f"gr.option('glossy_sampler', {self.rng.randint(0, 1)})")
        if c >= 8:
            n = self.rng.randint(1, 2)
            self.emit(f"gr.antialias{{sampler = '{self.rng.choice(['none', 'random', 'uniform', 'jittered', 'adaptive'])}', "
                      f"samples = {n * n}, threshold = {num(self.u(0, 0.5))}, depth = {self.rng.randint(0, 2)}}}")
        if c >= 12 and self.coin(0.6):
            self.emit(f"gr.tone_map{{operator = '{self.rng.choice(['none', 'global', 'local'])}', "
                      f"key = {num(self.u(0.01, 1))}, exposure = {num(self.u(-5, 5))}, "
                      f"srgb = {str(self.coin()).lower()}}}")
        if c >= 13 and self.coin(0.5):
            self.emit(f"gr.lens{{aperture = {num(self.u(0, 1))}, focus = {num(self.u(0.5, 20))}, "
                      f"samples = {self.rng.randint(1, 2)}, shape = '{self.rng.choice(['disk', 'square'])}'}}")
        if c >= 16 and self.coin(0.5):
            fields = [f"count = {self.rng.randint(1, 3000)}", f"passes = {self.rng.randint(1, 3)}",
                      f"alpha = {num(self.u(0.05, 0.95))}",
                      f"method = '{self.rng.choice(['progressive', 'classic'])}'",
                      f"k = {self.rng.choice([0, 0, self.rng.randint(1, 50)])}",
                      f"caustics = {str(self.coin(0.8)).lower()}",
                      f"indirect = {str(self.coin()).lower()}"]
            if self.coin():
                fields.append(f"radius = {num(10 ** self.u(-3, 0.5))}")
            self.emit("gr.photons{" + ", ".join(fields) + "}")
        if c >= 17 and self.coin(0.3):
            self.emit(f"gr.fog({self.medium()})")
        if c >= 18 and self.coin(0.6):
            self.emit(f"gr.integrator{{method = 'path', max_depth = {self.rng.randint(1, 8)}, "
                      f"roulette = {self.rng.randint(0, 4)}}}")

    def scene(self):
        self.emit("local root = gr.node('root')")
        for g in range(self.rng.randint(1, 3)):
            group = f"g{g}"
            self.emit(f"local {group} = gr.node('{group}')")
            self.transforms(group)
            parent = "root" if g == 0 or self.coin() else f"g{g - 1}"
            self.emit(f"{parent}:add_child({group})")
            for k in range(self.rng.randint(1, 3)):
                name = f"o{g}_{k}"
                self.obj(name)
                self.emit(f"{group}:add_child({name})")
        self.options()
        width = self.rng.randint(24, 48)
        height = width * 3 // 4
        # The eye looks at the scene's middle, give or take, so that most images show shapes.
        eye = self.direction(self.u(4, 12))
        view = [-e + j for e, j in zip(eye, self.direction(self.u(0, 4)))]
        self.emit(f"gr.render(root, 'soak.png', {width}, {height}, "
                  f"{triple(eye)}, {triple(view)}, "
                  f"{triple(self.direction())}, {num(self.u(5, 150))}, {self.colour(0, 0.4)}, "
                  f"{{{self.lights()}}})")
        return "\n".join(self.lines) + "\n"


def limits(rng):
    """--max-memory and --time-limit for one run: mostly ample, at times tight enough to refuse
    the scene (1 to 64 MiB) or stop it (1 or 2 s)."""
    memory = f"{rng.randint(1, 64)}M" if rng.random() < 0.3 else f"{rng.randint(1, 4)}G"
    seconds = rng.choice([1, 2]) if rng.random() < 0.3 else 600
    return memory, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, help="the repository, for meshes and images")
    parser.add_argument("--out", required=True)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--first", type=int, default=0)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    root = os.path.abspath(args.root)
    with open(os.path.join(args.out, "index.txt"), "w") as index:
        for i in range(args.first, args.first + args.count):
            rng = random.Random(args.seed * 1000003 + i)
            chapter = rng.randint(1, len(MODULES))
            features = ",".join(MODULES[:chapter])
            memory, seconds = limits(rng)
            lua = SceneWriter(rng, chapter, root).scene()
            name = os.path.join(args.out, f"scene-{i:05d}.lua")
            with open(name, "w") as f:
                f.write(f"-- soak scene {i} of seed {args.seed}: chapter {chapter}, "
                        f"--features={features} --max-memory {memory} --time-limit {seconds}\n")
                f.write(lua)
            index.write(f"{name} {chapter} {features} {memory} {seconds}\n")


if __name__ == "__main__":
    main()
