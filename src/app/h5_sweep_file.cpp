#include "app/h5_sweep_file.h"

#include <limits>

#include "h5/h5_file.h"
#include "output/staged_path.h"

namespace cb {

void write_h5_sweep(const std::string& path, const Grid& grid, PointRange range,
                    const std::vector<FirstBreak>& results, const ShardRecord& record) {
  StagedPath staged(path);
  {
    h5::Writer w(staged.temp());
    const std::uint64_t n = results.size();
    const std::uint64_t chunk = std::max<std::uint64_t>(1, std::min<std::uint64_t>(n, 65536));
    for (std::size_t k = 0; k < grid.axes.size(); ++k) {
      std::vector<double> column(n);
      for (std::size_t i = 0; i < n; ++i) column[i] = grid.point(range.first + i)[k];
      const std::string name = "/sweep/" + grid.axes[k].key;
      w.append(w.dataset({name, 0, chunk, 1, 0}), column.data(), n);
      w.attr(name, "description", "the swept value, " + grid.axes[k].spec);
    }
    std::vector<std::int64_t> spring(n, -1);
    std::vector<double> tau(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < n; ++i)
      if (results[i].broke) spring[i] = results[i].spring, tau[i] = results[i].tau;
    w.append_ints(w.dataset({"/sweep/spring", 0, chunk, 1, 0, true}), spring.data(), n);
    w.attr("/sweep/spring", "description",
           std::string("first spring to break: 0 the pull string, -1 none by t_end"));
    w.append(w.dataset({"/sweep/tau", 0, chunk, 1, 0}), tau.data(), n);
    w.attr("/sweep/tau", "description", std::string("tau of the first break; NaN: none"));
    w.attr("/", "scene", record.scene);
    w.attr("/", "scene_hash", record.scene_hash);
    w.attr("/", "solver", record.solver);
    w.attr("/", "header", record.header);
    w.attr("/", "version", record.version);
    w.attr("/", "record", record_json(record));
    w.close();
  }
  staged.commit();
}

}  // namespace cb
