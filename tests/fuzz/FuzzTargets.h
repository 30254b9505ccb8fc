#pragma once
/// @file FuzzTargets.h
/// The fuzz targets: one entry per reader of user-supplied bytes, each given one input. An input
/// may be refused with modeflow::Error (whose message must be printable); anything else, a
/// FuzzFinding (a broken promise of the reader) or a sanitizer report, is a finding. libFuzzer
/// drives them (LibFuzzerMain.cpp, one executable each); FuzzRegressionTest replays the inputs
/// they once failed on. Each returns whether the input was accepted (and kept the promises made
/// of what is accepted), false when it was refused.

#include <string_view>

namespace modeflow::fuzz {

/// parseScene on the input as scene text.
bool sceneLoader(std::string_view bytes);
/// readCache on the input as a cache file (or, without the cache magic, as a cache's payload
/// under a valid header and checksum, so the decoder itself is reached).
bool cacheReader(std::string_view bytes);
/// loadMeshShape on the input as an OBJ file.
bool objReader(std::string_view bytes);
/// readCheckpoint on the input as a checkpoint (or, without the magic, as a checkpoint's body
/// under a valid header and checksum).
bool checkpointReader(std::string_view bytes);
/// parseInputScript on the input as a `stir --script` file.
bool inputScript(std::string_view bytes);

}  // namespace modeflow::fuzz
