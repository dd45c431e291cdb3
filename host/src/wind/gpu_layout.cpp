// boreas: compile-time proof that the host and the kernels agree on the shared structs.
#include <cstddef>

#include "boreas/boreas.h"
#include "shared/wind_types.h"

static_assert(sizeof(BoreasGpuWave) == 32, "BoreasGpuWave layout");
static_assert(offsetof(BoreasGpuWave, phase_cycles) == 16, "BoreasGpuWave.phase_cycles offset");
static_assert(offsetof(BoreasGpuWave, sharpness) == 20, "BoreasGpuWave.sharpness offset");
static_assert(sizeof(BoreasGpuWave) == BOREAS_WAVE_FLOATS * sizeof(float), "BOREAS_WAVE_FLOATS");
static_assert(offsetof(BoreasGpuWave, phase_cycles) == BOREAS_WAVE_PHASE_WORD * sizeof(float),
              "BOREAS_WAVE_PHASE_WORD");
static_assert(sizeof(BoreasGpuGrid) == 40, "BoreasGpuGrid layout");
static_assert(offsetof(BoreasGpuGrid, fade_per_cell) == 32, "BoreasGpuGrid.fade_per_cell offset");
static_assert(offsetof(BoreasGpuGrid, nx) == 4 && offsetof(BoreasGpuGrid, nz) == 20, "BoreasGpuGrid offsets");
static_assert(sizeof(BoreasGpuForcing) == 48, "BoreasGpuForcing layout");
static_assert(offsetof(BoreasGpuForcing, uniform_weight) == 32, "BoreasGpuForcing weights offset");
static_assert(sizeof(BoreasGpuGridStep) == 32, "BoreasGpuGridStep layout");
static_assert(offsetof(BoreasGpuGridStep, forcing_count) == 16, "BoreasGpuGridStep.forcing_count");
