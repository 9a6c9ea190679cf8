#include "verify/at_once.h"

#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace tp {

std::vector<EngineRun>
render_at_once(const std::vector<Engine*>& engines, std::vector<EngineRequest> requests,
               const std::function<EngineRun(Engine&, const EngineRequest&)>& render,
               std::atomic<bool>& stop, const AtOnceProgress& progress) {
    std::map<int, std::vector<size_t>> lanes;
    for (size_t k = 0; k < engines.size(); ++k) lanes[engines[k]->lane()].push_back(k);
    std::vector<EngineRun> runs(engines.size());
    std::mutex mutex; // guards `progress` calls and `failure`
    std::exception_ptr failure;
    for (size_t k = 0; k < requests.size(); ++k) {
        requests[k].stop = &stop;
        requests[k].progress = [&, k](double f) {
            const std::lock_guard<std::mutex> lock(mutex);
            if (progress) progress(k, f);
        };
    }
    std::vector<std::thread> threads;
    for (const auto& [lane, members] : lanes)
        threads.emplace_back([&, members = members] {
            for (size_t k : members) {
                if (stop.load()) return;
                try {
                    runs[k] = render(*engines[k], requests[k]);
                } catch (...) {
                    const std::lock_guard<std::mutex> lock(mutex);
                    if (!failure) failure = std::current_exception();
                    stop.store(true);
                    return;
                }
            }
        });
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
    return runs;
}

} // namespace tp
