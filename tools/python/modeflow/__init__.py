"""modeflow: model-reduced fluid simulation from Python.

    import modeflow
    scene = modeflow.Scene.load("scenes/plume_2d.toml")
    sim = modeflow.Simulation(scene, device="cpu")
    sim.step(10)
    print(sim.time, sim.energy, sim.density.shape)

Scene, Simulation, inspect and Error are the native module's (tools/python/README.md).
"""

from ._modeflow import Error, Scene, Simulation, inspect

__all__ = ["Error", "Scene", "Simulation", "inspect"]
