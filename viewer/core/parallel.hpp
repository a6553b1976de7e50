// Splits [0, count) into one contiguous range per core and sums what `part(begin, end)` returns over
// them (a type with +=). For large reductions (the fitter's sums over a million BRDF samples); small
// counts run on the calling thread.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace fxview {

template <typename Sum, typename Part>
Sum parallel_sum(size_t count, const Part& part, size_t serial_below = 20000) {
    const size_t cores = std::max<size_t>(1, std::thread::hardware_concurrency());
    if (count < serial_below || cores == 1) return part(0, count);
    const size_t chunk = (count + cores - 1) / cores;
    std::vector<Sum> sums(cores);
    std::vector<std::exception_ptr> failures(cores);
    {
        std::vector<std::jthread> workers;
        for (size_t t = 1; t < cores; ++t)
            workers.emplace_back([&, t] {
                try {
                    sums[t] = part(std::min(count, t * chunk), std::min(count, (t + 1) * chunk));
                } catch (...) {
                    failures[t] = std::current_exception();
                }
            });
        sums[0] = part(0, std::min(count, chunk));
    }
    for (const auto& failure : failures)
        if (failure) std::rethrow_exception(failure);
    Sum total = sums[0];
    for (size_t t = 1; t < cores; ++t) total += sums[t];
    return total;
}

}  // namespace fxview
