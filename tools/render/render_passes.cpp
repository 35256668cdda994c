#include "tools/render/render_passes.h"

namespace wt {

bool RenderPassHooks::pass_done(const Film& film, const PassReport& report) {
    progress_.pass_done(report);
    if (report.last) return true;
    for (Periodic& p : actions_) {
        if (report.seconds - p.last_run < p.interval) continue;
        progress_.finish();  // anything the action prints starts on a line of its own
        p.action(film, report);
        p.last_run = report.seconds;
    }
    return true;
}

}  // namespace wt
