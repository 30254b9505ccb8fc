#include "engine/run/GridFrames.h"

#include <span>
#include <utility>
#include <vector>

#include "engine/output/ParticleFrame.h"

namespace modeflow {

GridFrames::GridFrames(Simulator& simulator, const RunInputs& run, GridFrameFiles files)
    : mSimulator(simulator),
      mRun(run),
      mFiles(std::move(files)),
      mBasisGrid(MacGrid::fromSpec(run.cache.grid)) {
    if (mFiles.previews)
        mPreview = std::make_unique<FramePreview>(mSimulator.smokeGrid(), mRun.smokeMask,
                                                  mFiles.previewDevice);
}

VdbFrame gridVdbFrame(const Simulator& simulator, std::span<const std::uint8_t> fluidMask,
                      const MacGrid& basisGrid, const SmokeFields& smoke,
                      std::span<const double> faceVelocity, std::span<const double> faceMagnetic,
                      int frame, std::string sceneHash, bool halfFloat) {
    VdbFrame vdb;
    vdb.smokeGrid = simulator.smokeGrid();
    vdb.basisGrid = basisGrid;
    vdb.density = std::span<const double>(smoke.density);
    if (simulator.settings().simulatesTemperature())
        vdb.temperature = std::span<const double>(smoke.temperature);
    vdb.fuel = std::span<const double>(smoke.fuel);  // empty without fire
    vdb.flame = std::span<const double>(smoke.flame);
    vdb.faceVelocity = faceVelocity;
    vdb.faceMagnetic = faceMagnetic;
    vdb.fluidMask = fluidMask;
    vdb.frame = frame;
    vdb.time = simulator.time();
    vdb.sceneHash = std::move(sceneHash);
    vdb.modeflowVersion = MODEFLOW_VERSION;
    vdb.options.halfFloat = halfFloat;
    return vdb;
}

std::filesystem::path GridFrames::frameFile(int frame) const {
    return mFiles.folder / frameFileName(mFiles.sceneName, frame);
}

FrameOutput GridFrames::readFrame(int frame, const std::filesystem::path& picture,
                                  FrameProgress& bar) {
    const bool temperature = settings().simulatesTemperature();
    FrameOutput out;
    Checkpoint& state = out.checkpoint;
    state.frame = frame;
    state.time = mSimulator.time();
    bar.timed("reading fields", [&] {
        state.smoke = mSimulator.smoke();
        state.velocity = mSimulator.velocity();
        state.magnetic = mSimulator.magneticField();
        state.carry = mSimulator.carry();
        if (!settings().particles.empty()) state.particles = mSimulator.particles();
    });
    std::vector<double> faceVelocity =
        bar.timed("reading fields", [&] { return mSimulator.faceVelocity(); });
    std::vector<double> faceMagnetic =
        bar.timed("reading fields", [&] { return mSimulator.faceMagneticField(); });
    if (!picture.empty() && mPreview)
        bar.timed("previews",
                  [&] { mPreview->write(picture, state.smoke, temperature, state.particles); });
    // The VDB frame's metadata now (the simulation steps on), its fields pointed at again where
    // they then lie when it is written.
    VdbFrame vdb = gridVdbFrame(mSimulator, mRun.smokeMask, mBasisGrid, state.smoke, faceVelocity,
                                faceMagnetic, frame, mFiles.sceneHash, mFiles.halfFloat);
    const bool particles = !settings().particles.empty();
    out.writeFiles =
        [vdb = std::move(vdb), faceVelocity = std::move(faceVelocity),
         faceMagnetic = std::move(faceMagnetic), particles, temperature, file = frameFile(frame),
         particleFile = mFiles.folder / particleFrameFileName(mFiles.sceneName, frame),
         sceneHash = mFiles.sceneHash](const Checkpoint& state, FrameProgress& bar) mutable {
            vdb.density = state.smoke.density;
            if (temperature) vdb.temperature = state.smoke.temperature;
            vdb.faceVelocity = faceVelocity;
            vdb.faceMagnetic = faceMagnetic;
            bar.timed("VDB files", [&] { writeVdbFrame(file, vdb); });
            if (particles) {
                const ParticleFrame points{state.particles.position, state.particles.velocity,
                                           state.frame, state.time, sceneHash};
                bar.timed("particle files", [&] { writeParticleFrame(particleFile, points); });
            }
        };
    return out;
}

void GridFrames::restore(const Checkpoint& from) {
    mSimulator.restore(from.time, from.velocity, from.smoke);
    if (settings().mhd) mSimulator.setMagneticField(from.magnetic);
    mSimulator.setCarry(from.carry);
    mSimulator.setParticles(from.particles);
}

}  // namespace modeflow
