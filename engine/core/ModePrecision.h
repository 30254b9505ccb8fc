#pragma once
/// @file ModePrecision.h
/// How a backend stores the velocity basis: float32, or float16 for half the memory and
/// bandwidth of the reconstruction and force projection (~1e-3 relative error in the grid
/// velocity). A scene chooses it with `[simulation] basis_precision`; the CPU reference always
/// computes in double and ignores it.

namespace modeflow {

enum class ModePrecision { Float32, Float16 };

}  // namespace modeflow
