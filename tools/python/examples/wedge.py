#!/usr/bin/env python3
"""A wedge: one scene run for several buoyancy values, each into a folder of its own, in parallel
processes (the basis is precomputed once, before they start, and shared through the cache).

    PYTHONPATH=build/python python3 tools/python/examples/wedge.py scenes/jet_2d.toml \\
        --buoyancy 0.5 1 2 --frames 24 --out wedge

writes wedge/buoyancy_0.5/jet_2d_0001.vdb, ... (the frames `modeflow run` would write).
"""

import argparse
import multiprocessing
import pathlib
import tomllib

import modeflow


def run_member(scene_file, buoyancy, frames, out, device, cache_dir):
    scene_file = pathlib.Path(scene_file)
    schema = tomllib.loads(scene_file.read_text())
    schema.setdefault("smoke", {})["buoyancy"] = buoyancy
    scene = modeflow.Scene.from_dict(schema, name=scene_file.stem, folder=scene_file.parent)
    sim = modeflow.Simulation(scene, device=device, cache_dir=cache_dir)
    folder = pathlib.Path(out) / f"buoyancy_{buoyancy:g}"
    folder.mkdir(parents=True, exist_ok=True)
    for frame in range(1, frames + 1):
        sim.step(sim.steps_per_frame)
        sim.write_vdb(folder / f"{scene.name}_{frame:04d}.vdb")
    return str(folder)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--buoyancy", type=float, nargs="+", required=True)
    parser.add_argument("--frames", type=int, default=24)
    parser.add_argument("--out", default="wedge")
    parser.add_argument("--device", default="vulkan")
    parser.add_argument("--cache-dir", default=None)
    parser.add_argument("--jobs", type=int, default=None, help="processes (default: one per value)")
    args = parser.parse_args()
    # Precompute once here rather than in every process at once.
    modeflow.inspect(args.scene, cache_dir=args.cache_dir, progress=print)
    members = [(args.scene, b, args.frames, args.out, args.device, args.cache_dir) for b in args.buoyancy]
    # spawn: every process opens its own Vulkan device; a forked copy of an open one is unusable.
    with multiprocessing.get_context("spawn").Pool(args.jobs or len(members)) as pool:
        for folder in pool.starmap(run_member, members):
            print(folder)


if __name__ == "__main__":
    main()
