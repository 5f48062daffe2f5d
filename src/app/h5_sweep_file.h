// A sweep's table as HDF5 (`sweep --h5 FILE`): one dataset per varied key, the first broken
// spring and its tau, over the shard's points in grid order (the CSV's rows), with the sweep's
// record (cluster/shard_record.h) as attributes.
//
//   /sweep/<key>       points   the key's value at each point (doubles)
//   /sweep/spring      points   first spring to break (int64; 0 the pull string, -1 none)
//   /sweep/tau         points   when (NaN when nothing broke by t_end)
//   /  attributes      scene, scene_hash, solver, header, version, record (its JSON)
#pragma once

#include <string>
#include <vector>

#include "cluster/grid.h"
#include "cluster/shard_record.h"
#include "exact/first_break.h"

namespace cb {

// Written beside `path` and renamed into place; throws OutputError / h5::H5Error.
void write_h5_sweep(const std::string& path, const Grid& grid, PointRange range,
                    const std::vector<FirstBreak>& results, const ShardRecord& record);

}  // namespace cb
