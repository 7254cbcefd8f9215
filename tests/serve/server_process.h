// `penumbra serve` as a user starts it, in the background: on lavapipe (or PENUMBRA_TEST_DEVICE)
// with Vulkan validation on, its standard output read until the `serving` line gives the port,
// its standard error kept, and stopped with a signal. Every wait has a deadline.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "../gpu/binary_path.h"

namespace penumbra::test {

class ServerProcess {
public:
    using Clock = std::chrono::steady_clock;

    // Starts `penumbra serve ARGS...`; call waitUntilServing() before connecting.
    explicit ServerProcess(const std::vector<std::string>& args) {
        int out[2], err[2];
        if (pipe(out) != 0 || pipe(err) != 0) return;
        pid_ = fork();
        if (pid_ == 0) {
            dup2(out[1], 1);
            dup2(err[1], 2);
            close(out[0]), close(err[0]), close(out[1]), close(err[1]);
            const char* device = std::getenv("PENUMBRA_TEST_DEVICE");
            setenv("PENUMBRA_DEVICE", device && *device ? device : "llvmpipe", 1);
            setenv("PENUMBRA_VALIDATION", "1", 1);
            std::vector<std::string> all{penumbraBinary(), "serve"};  // PENUMBRA_BINARY on the GPU host
            all.insert(all.end(), args.begin(), args.end());
            std::vector<char*> argv;
            for (std::string& a : all) argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
        close(out[1]), close(err[1]);
        outFd_ = out[0], errFd_ = err[0];
        fcntl(outFd_, F_SETFL, O_NONBLOCK);
        fcntl(errFd_, F_SETFL, O_NONBLOCK);
    }
    ~ServerProcess() {
        if (running()) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
        if (outFd_ >= 0) close(outFd_);
        if (errFd_ >= 0) close(errFd_);
    }
    ServerProcess(const ServerProcess&) = delete;
    ServerProcess& operator=(const ServerProcess&) = delete;

    // The port from `penumbra: serving http://127.0.0.1:PORT/`, or nothing if the process ended
    // or said nothing within the deadline.
    std::optional<std::string> waitUntilServing(std::chrono::seconds deadline = std::chrono::seconds(120)) {
        const auto end = Clock::now() + deadline;
        while (Clock::now() < end) {
            pump(100);
            const std::size_t at = out_.find("penumbra: serving http://");
            const std::size_t eol = out_.find('\n', at);
            if (at != std::string::npos && eol != std::string::npos) {
                const std::string line = out_.substr(at, eol - at);
                const std::size_t colon = line.rfind(':'), slash = line.find('/', colon);
                return line.substr(colon + 1, slash - colon - 1);
            }
            if (!running()) return std::nullopt;
        }
        return std::nullopt;
    }

    // Sends `signal` and waits for the exit: its code, or -1 when it did not end in time or was
    // killed by a signal.
    int stop(int signal = SIGTERM, std::chrono::seconds deadline = std::chrono::seconds(30)) {
        kill(pid_, signal);
        return wait(deadline);
    }
    int wait(std::chrono::seconds deadline) {
        const auto end = Clock::now() + deadline;
        while (Clock::now() < end) {
            pump(20);
            int status = 0;
            if (waitpid(pid_, &status, WNOHANG) == pid_) {
                exited_ = true;
                pump(0);
                return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            }
        }
        return -1;
    }

    bool running() {
        if (exited_ || pid_ <= 0) return false;
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) exited_ = true;
        return !exited_;
    }
    pid_t pid() const { return pid_; }
    const std::string& err() {
        pump(0);
        return err_;
    }
    const std::string& out() {
        pump(0);
        return out_;
    }

private:
    // Reads what the pipes hold, waiting up to `ms` for something.
    void pump(int ms) {
        pollfd fds[2] = {{outFd_, POLLIN, 0}, {errFd_, POLLIN, 0}};
        poll(fds, 2, ms);
        char buffer[4096];
        for (auto [fd, text] : {std::pair{outFd_, &out_}, std::pair{errFd_, &err_}})
            for (ssize_t n; fd >= 0 && (n = read(fd, buffer, sizeof buffer)) > 0;) text->append(buffer, std::size_t(n));
    }

    pid_t pid_ = -1;
    int outFd_ = -1, errFd_ = -1;
    bool exited_ = false;
    std::string out_, err_;
};

}  // namespace penumbra::test
