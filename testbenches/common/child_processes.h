// Child processes of a program, in one place for the three programs that run them: bench_jobs.h
// (a random run split over processes), render_pipeline's sweep (one process per configuration) and
// perf_models (each case in a fresh process, as SystemC elaborates once per process). Spawned with
// posix_spawn, at most `parallel` at a time, standard output (and optionally error) into a file.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace shading::tb {

struct child_spec {
    std::string program;            // the file executed ("/proc/self/exe": this program again)
    std::vector<std::string> args;  // its argv, args[0] included
    std::string out;                // standard output goes to this file (empty: inherited)
    bool err_too = false;           // standard error into the same file
};

// The status a child ended with: its exit code, 128 + the signal that killed it, or -1 when it
// could not be started.
inline int child_status(int wait_status) {
    if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
    if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
    return -1;
}

// Runs `count` children, child i as spec(i), at most `parallel` at once; done(i, status) is called
// as each ends (in the order they end). Returns every child's status, by index.
inline std::vector<int> run_children(std::size_t count, unsigned parallel,
                                     const std::function<child_spec(std::size_t)>& spec,
                                     const std::function<void(std::size_t, int)>& done = {}) {
    std::vector<int> status(count, -1);
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0, ended = 0;
    auto finish = [&](std::size_t i, int s) {
        status[i] = s;
        ++ended;
        if (done) done(i, s);
    };
    if (parallel == 0) parallel = 1;
    while (ended < count) {
        while (running.size() < parallel && next < count) {
            const std::size_t i = next++;
            const child_spec c = spec(i);
            std::vector<char*> argv;
            for (const auto& a : c.args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            posix_spawn_file_actions_t fa;
            posix_spawn_file_actions_init(&fa);
            if (!c.out.empty()) {
                posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
                if (c.err_too) posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
            }
            pid_t pid = -1;
            const int rc = posix_spawn(&pid, c.program.c_str(), &fa, nullptr, argv.data(), environ);
            posix_spawn_file_actions_destroy(&fa);
            if (rc != 0) finish(i, -1);
            else running[pid] = i;
        }
        if (running.empty()) continue;  // every remaining child failed to start
        int st = 0;
        const pid_t p = ::waitpid(-1, &st, 0);
        if (p < 0) {  // no child left to wait for (cannot happen while `running` holds one): give up
            for (const auto& [pid, i] : running) finish(i, -1);
            running.clear();
            continue;
        }
        const auto it = running.find(p);
        if (it == running.end()) continue;  // not one of ours
        const std::size_t i = it->second;
        running.erase(it);
        finish(i, child_status(st));
    }
    return status;
}

}  // namespace shading::tb
