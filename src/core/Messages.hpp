#pragma once
// The message log (.mess, echoed on stdout) and the result file (.resu).
// Everything a command wants the user to read goes through here.
#include <fmt/format.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/Message.hpp"

namespace ma {

class Messages {
public:
    static Messages& instance();

    // A line (or several) of the message log.
    void info(const std::string& text);
    template <class... Args>
    void infof(fmt::format_string<Args...> f, Args&&... args) {
        info(fmt::format(f, std::forward<Args>(args)...));
    }
    // An alarm box (<A> ID) in code_aster's style; counted for the final diagnostic. Its text
    // comes from an area's table (core/Message.hpp), never from an inline literal.
    template <class... A>
    void alarm(const Message<A...>& m, const std::type_identity_t<A>&... args) {
        alarmBox(m.id, format(m, args...));
    }
    void alarm(const FormattedMessage& m) { alarmBox(m.id, m.text); }
    // Text for the result file (.resu): TEST lines, IMPR_TABLE output. Also echoed in the log.
    void result(const std::string& text);

    // The .mess is a log: from this call on, every line is also written to `fd` at once (the text
    // logged so far first), so that `tail -f` follows the run and a killed run keeps its log.
    // With its `path`, a descriptor the command file closed (os.close) or that now names another
    // file is noticed at the next line and the log opened again by its path, at its end. Only the
    // process that called streamTo writes (a child forked by the command file writes nothing).
    void streamTo(int fd, const std::string& path = {});
    int streamFd() const { return fd_; }
    // errno of the first write to the stream that failed (0: none).
    int streamError() const { return streamError_; }
    // Emergency stop from another thread: the calling thread keeps the log, every other thread
    // blocks at its next message (the process is about to end). A thread that holds the log for
    // long (its echo blocked on a stdout pipe nobody reads: mpirun stopping) is not waited for
    // beyond a moment; emergency() then writes to the .mess all the same, without the echo.
    void freeze();
    // The emergency's lines, after freeze(): as info(), the echo only when stdout takes it now.
    void emergency(const std::string& text);

    int alarmCount() const { return alarms_; }
    // DEBUT(IGNORE_ALARM=...): these alarms are neither printed nor counted for the diagnostic;
    // ignoredAlarms() gives how many of each were raised (for the end of the log).
    void ignoreAlarms(const std::vector<std::string>& ids);
    const std::map<std::string, int>& ignoredAlarms() const { return ignored_; }
    const std::string& messText() const { return mess_; }
    const std::string& resuText() const { return resu_; }
    void setEcho(bool echo) { echo_ = echo; }
    void reset();

private:
    void alarmBox(const std::string& id, const std::string& text);
    void write(const std::string& text);
    bool streamIsTheLog() const;
    void reopenStream();

    std::recursive_timed_mutex mutex_;
    bool frozen_ = false;  // freeze() holds the mutex
    int fd_ = -1;
    int streamError_ = 0;
    std::string path_;  // of the stream, "" when it is not to be reopened
    unsigned long dev_ = 0, ino_ = 0;
    int owner_ = 0;  // pid of the writing process
    std::string mess_, resu_;
    int alarms_ = 0;
    std::map<std::string, int> ignored_;  // id -> times raised
    bool echo_ = true;
};

inline Messages& msg() { return Messages::instance(); }

}  // namespace ma
