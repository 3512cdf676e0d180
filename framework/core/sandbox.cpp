#include "core/sandbox.h"

#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/capability.h>
#include <linux/sched.h>
#include <linux/sockios.h>
#include <pwd.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "core/error.h"
#include "core/number_format.h"

namespace pathway {
namespace {

// Landlock's kernel interface (linux/landlock.h), written out: Debian 12's headers predate the
// network rules (ABI 4) and the scopes (ABI 6), and the kernel, not the headers, decides.
namespace landlock {
struct RulesetAttributes {
  uint64_t handledAccessFs;
  uint64_t handledAccessNet;  // ABI 4+
  uint64_t scoped;            // ABI 6+
};
struct PathBeneath {
  uint64_t allowedAccess;
  int32_t parentFd;
} __attribute__((packed));
constexpr uint32_t kCreateRulesetVersion = 1u << 0;
constexpr int kRulePathBeneath = 1;
constexpr uint64_t kExecute = 1ull << 0, kWriteFile = 1ull << 1, kReadFile = 1ull << 2,
                   kReadDir = 1ull << 3, kRemoveDir = 1ull << 4, kRemoveFile = 1ull << 5,
                   kMakeChar = 1ull << 6, kMakeDir = 1ull << 7, kMakeReg = 1ull << 8,
                   kMakeSock = 1ull << 9, kMakeFifo = 1ull << 10, kMakeBlock = 1ull << 11,
                   kMakeSym = 1ull << 12, kRefer = 1ull << 13 /* ABI 2 */,
                   kTruncate = 1ull << 14 /* ABI 3 */, kIoctlDev = 1ull << 15 /* ABI 5 */;
constexpr uint64_t kBindTcp = 1ull << 0, kConnectTcp = 1ull << 1;                   // ABI 4
constexpr uint64_t kScopeAbstractUnixSocket = 1ull << 0, kScopeSignal = 1ull << 1;  // ABI 6

int abi() {
  const long version = syscall(SYS_landlock_create_ruleset, nullptr, 0, kCreateRulesetVersion);
  return version < 0 ? 0 : static_cast<int>(version);
}

// Every file-system right this ABI knows: all of them are refused unless a rule grants them.
uint64_t handledFs(int abi) {
  uint64_t rights = kExecute | kWriteFile | kReadFile | kReadDir | kRemoveDir | kRemoveFile |
                    kMakeChar | kMakeDir | kMakeReg | kMakeSock | kMakeFifo | kMakeBlock | kMakeSym;
  if (abi >= 2) rights |= kRefer;
  if (abi >= 3) rights |= kTruncate;
  if (abi >= 5) rights |= kIoctlDev;
  return rights;
}

// The rights a rule on a file may carry (directory rights on a file are refused).
uint64_t fileRights(int abi) {
  return kExecute | kWriteFile | kReadFile | (abi >= 3 ? kTruncate : 0) |
         (abi >= 5 ? kIoctlDev : 0);
}
}  // namespace landlock

struct FileDescriptor {
  int fd = -1;
  explicit FileDescriptor(int value) : fd(value) {}
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Grants `rights` (narrowed to a file's) below `path`; a path that does not exist is skipped.
void addPathRule(int ruleset, const std::string& path, uint64_t rights, int abi) {
  const FileDescriptor target(::open(path.c_str(), O_PATH | O_CLOEXEC));
  if (target.fd < 0) return;
  struct stat info;
  if (::fstat(target.fd, &info) != 0) return;
  if (!S_ISDIR(info.st_mode)) rights &= landlock::fileRights(abi);
  const landlock::PathBeneath rule{rights, target.fd};
  if (syscall(SYS_landlock_add_rule, ruleset, landlock::kRulePathBeneath, &rule, 0) != 0)
    throw PathwayError("sandbox: Landlock refused a rule for " + path + ": " +
                       std::strerror(errno));
}

void applyLandlock(const SandboxPolicy& policy, int abi) {
  landlock::RulesetAttributes attributes{landlock::handledFs(abi), 0, 0};
  size_t size = sizeof(uint64_t);
  if (abi >= 4) {
    attributes.handledAccessNet = landlock::kBindTcp | landlock::kConnectTcp;  // no port allowed
    size = 2 * sizeof(uint64_t);
  }
  if (abi >= 6) {
    attributes.scoped = landlock::kScopeAbstractUnixSocket | landlock::kScopeSignal;
    size = sizeof attributes;
  }
  const FileDescriptor ruleset(
      static_cast<int>(syscall(SYS_landlock_create_ruleset, &attributes, size, 0)));
  if (ruleset.fd < 0)
    throw PathwayError(std::string("sandbox: Landlock refused the ruleset: ") +
                       std::strerror(errno));
  const uint64_t read = landlock::kReadFile | landlock::kReadDir | landlock::kExecute;
  std::vector<std::string> readable = systemReadablePaths();
  readable.insert(readable.end(), policy.readable.begin(), policy.readable.end());
  for (const std::string& path : readable) addPathRule(ruleset.fd, path, read, abi);
  // /dev/null is written to as well (a compiler's discarded output).
  addPathRule(ruleset.fd, "/dev/null", read | landlock::kWriteFile, abi);
  const uint64_t write = read | landlock::kWriteFile | landlock::kMakeReg | landlock::kMakeDir |
                         (policy.removesFiles ? landlock::kRemoveFile | landlock::kRemoveDir : 0) |
                         (abi >= 2 ? landlock::kRefer : 0) | (abi >= 3 ? landlock::kTruncate : 0);
  for (const std::string& folder : policy.writable) addPathRule(ruleset.fd, folder, write, abi);
  if (syscall(SYS_landlock_restrict_self, ruleset.fd, 0) != 0)
    throw PathwayError(std::string("sandbox: Landlock could not restrict this process: ") +
                       std::strerror(errno));
}

bool seccompAvailable() {
  // 0: the kernel has seccomp and this process is not in strict mode.
  return ::prctl(PR_GET_SECCOMP, 0, 0, 0, 0) == 0;
}

void applySeccomp(const SandboxPolicy& policy) {
  const std::unique_ptr<void, void (*)(scmp_filter_ctx)> filter(seccomp_init(SCMP_ACT_ALLOW),
                                                                seccomp_release);
  if (!filter) throw PathwayError("sandbox: seccomp_init failed");
  int failed = 0;
  // What no stage or compiler does: the process is killed on the spot (SIGSYS), so that the
  // attempt fails the case instead of being quietly refused.
  auto forbid = [&](int syscallNumber) {
    if (syscallNumber < 0) return;  // not on this architecture
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_KILL_PROCESS, syscallNumber, 0);
  };
  // No network: a socket of any family but a local one kills. A local (UNIX) socket is refused
  // instead, since glibc itself asks for one on the quiet (a user-name lookup tries nscd first,
  // as bash does when SHELL is unset) and falls back to files; it never gets a socket to connect
  // to another process with. Nothing that reaches into another process, the kernel or around
  // these rules (io_uring performs its operations outside the system calls filtered here).
  failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EACCES), SCMP_SYS(socket), 1,
                             SCMP_A0(SCMP_CMP_EQ, AF_UNIX));
  failed |= seccomp_rule_add(filter.get(), SCMP_ACT_KILL_PROCESS, SCMP_SYS(socket), 1,
                             SCMP_A0(SCMP_CMP_NE, AF_UNIX));
  failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EACCES), SCMP_SYS(socketpair), 0);
  for (int number : {SCMP_SYS(ptrace),
                     SCMP_SYS(process_vm_readv),
                     SCMP_SYS(process_vm_writev),
                     SCMP_SYS(io_uring_setup),
                     SCMP_SYS(io_uring_enter),
                     SCMP_SYS(io_uring_register),
                     SCMP_SYS(bpf),
                     SCMP_SYS(perf_event_open),
                     SCMP_SYS(userfaultfd),
                     SCMP_SYS(keyctl),
                     SCMP_SYS(add_key),
                     SCMP_SYS(request_key),
                     SCMP_SYS(unshare),
                     SCMP_SYS(setns),
                     SCMP_SYS(mount),
                     SCMP_SYS(umount2),
                     SCMP_SYS(pivot_root),
                     SCMP_SYS(chroot),
                     SCMP_SYS(init_module),
                     SCMP_SYS(finit_module),
                     SCMP_SYS(delete_module),
                     SCMP_SYS(kexec_load),
                     SCMP_SYS(reboot),
                     SCMP_SYS(swapon),
                     SCMP_SYS(swapoff)})
    forbid(number);
  // No IPC that could outlive the process or reach another child: System V shared memory,
  // message queues and semaphores, and POSIX message queues (POSIX shared memory and named pipes
  // are files, which Landlock keeps to the process's own folder; UNIX sockets are refused above).
  for (int number : {SCMP_SYS(shmget), SCMP_SYS(shmat), SCMP_SYS(shmdt), SCMP_SYS(shmctl),
                     SCMP_SYS(msgget), SCMP_SYS(msgsnd), SCMP_SYS(msgrcv), SCMP_SYS(msgctl),
                     SCMP_SYS(semget), SCMP_SYS(semop), SCMP_SYS(semtimedop), SCMP_SYS(semctl),
                     SCMP_SYS(mq_open), SCMP_SYS(mq_unlink), SCMP_SYS(mq_timedsend),
                     SCMP_SYS(mq_timedreceive), SCMP_SYS(mq_notify), SCMP_SYS(mq_getsetattr)})
    forbid(number);
  // Another process's limits, priority, scheduling or memory placement: refused (a process may
  // still set its own, which its libraries do; pid 0 means itself). Two children of one grader
  // run as the same user, and would otherwise be each other's to slow down or starve.
  const auto refuseUnlessZero = [&](int syscallNumber, unsigned argument) {
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), syscallNumber, 1,
                               scmp_arg_cmp{argument, SCMP_CMP_NE, 0, 0});
  };
  refuseUnlessZero(SCMP_SYS(prlimit64), 0);
  refuseUnlessZero(SCMP_SYS(setpriority), 0);  // PRIO_PROCESS only: not a group's, not a user's
  refuseUnlessZero(SCMP_SYS(setpriority), 1);
  for (int number : {SCMP_SYS(sched_setscheduler), SCMP_SYS(sched_setparam),
                     SCMP_SYS(sched_setattr), SCMP_SYS(sched_setaffinity), SCMP_SYS(migrate_pages),
                     SCMP_SYS(move_pages), SCMP_SYS(get_robust_list)})
    refuseUnlessZero(number, 0);
  for (int number : {SCMP_SYS(ioprio_set), SCMP_SYS(pidfd_open), SCMP_SYS(pidfd_send_signal),
                     SCMP_SYS(pidfd_getfd), SCMP_SYS(process_madvise), SCMP_SYS(kcmp)})
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), number, 0);
  if (!policy.startsPrograms) {
    // Signals to itself only (Landlock's signal scope does the same from ABI 6 on; this holds
    // on older kernels too). raise() and abort() go through tgkill with this process's id. A
    // descriptor's owner (F_SETOWN and their like) would have the kernel send SIGIO to anyone.
    const auto self = static_cast<scmp_datum_t>(::getpid());
    for (int number :
         {SCMP_SYS(kill), SCMP_SYS(tgkill), SCMP_SYS(rt_sigqueueinfo), SCMP_SYS(rt_tgsigqueueinfo)})
      failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), number, 1,
                                 SCMP_A0(SCMP_CMP_NE, self));
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), SCMP_SYS(tkill), 0);
    for (int command : {F_SETOWN, F_SETOWN_EX, F_SETSIG})
      failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), SCMP_SYS(fcntl), 1,
                                 SCMP_A1(SCMP_CMP_EQ, static_cast<scmp_datum_t>(command)));
    for (unsigned long request :
         {static_cast<unsigned long>(FIOSETOWN), static_cast<unsigned long>(SIOCSPGRP)})
      failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(EPERM), SCMP_SYS(ioctl), 1,
                                 SCMP_A1(SCMP_CMP_EQ, static_cast<scmp_datum_t>(request)));
    // Threads only: a clone without CLONE_THREAD is a new process. clone3 passes its flags in
    // memory a filter cannot read, so it answers "not implemented", and glibc falls back to clone.
    for (int number : {SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(execve), SCMP_SYS(execveat)})
      forbid(number);
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    failed |= seccomp_rule_add(filter.get(), SCMP_ACT_KILL_PROCESS, SCMP_SYS(clone), 1,
                               SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
  }
  if (failed != 0) throw PathwayError("sandbox: a seccomp rule could not be added");
  // All threads, should any exist already (none should).
  seccomp_attr_set(filter.get(), SCMP_FLTATR_CTL_TSYNC, 1);
  const int loaded = seccomp_load(filter.get());
  if (loaded != 0)
    throw PathwayError(std::string("sandbox: the seccomp filter could not be loaded: ") +
                       std::strerror(-loaded));
}

void setLimit(int resource, uint64_t value) {
  if (value == 0) return;
  const rlimit limit{value, value};
  if (::setrlimit(resource, &limit) != 0)
    throw PathwayError(std::string("sandbox: setrlimit failed: ") + std::strerror(errno));
}

std::string limitsText(const SandboxPolicy& policy) {
  std::string text;
  auto add = [&text](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
#ifdef __SANITIZE_ADDRESS__
  // AddressSanitizer reserves terabytes of shadow memory: an address-space limit stops it.
  if (policy.addressSpaceBytes) add("memory not limited (an AddressSanitizer build)");
#else
  if (policy.addressSpaceBytes) add("memory " + bytesText(policy.addressSpaceBytes));
#endif
  if (policy.cpuSeconds) add("CPU " + std::to_string(policy.cpuSeconds) + " s");
  if (policy.openFiles) add(std::to_string(policy.openFiles) + " open files");
  if (policy.fileBytes) add("files up to " + bytesText(policy.fileBytes));
  return text;
}

// Root that could not become another user keeps its uid but nothing of its power: every
// capability leaves the bounding, ambient, effective, permitted and inheritable sets.
void dropEveryCapability() {
  for (int capability = 0; capability <= 63; ++capability)
    ::prctl(PR_CAPBSET_DROP, capability, 0, 0, 0);  // EINVAL past the kernel's last: ignored
  ::prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0);
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct none[2] = {};
  if (syscall(SYS_capset, &header, none) != 0)
    throw PathwayError(std::string("sandbox: could not drop root's capabilities: ") +
                       std::strerror(errno));
}

// Whether `uid` exists in this process's user namespace (/proc/self/uid_map: "inside outside
// count" lines; the initial namespace maps them all).
bool uidMapped(unsigned uid) {
  std::ifstream map("/proc/self/uid_map");
  for (unsigned long long inside, outside, count; map >> inside >> outside >> count;)
    if (uid >= inside && uid - inside < count) return true;
  return false;
}

// "user: uid 65534 (not root)", "user: uid 0 (root, without capabilities)": as the kernel sees
// this process now.
std::string actualUser() {
  uid_t real = 0, effective = 0, saved = 0;
  ::getresuid(&real, &effective, &saved);
  if (real != 0 && effective != 0 && saved != 0)
    return "user: uid " + std::to_string(effective) + " (not root)";
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct held[2] = {};
  const bool none = syscall(SYS_capget, &header, held) == 0 && held[0].effective == 0 &&
                    held[1].effective == 0 && held[0].permitted == 0 && held[1].permitted == 0;
  return std::string("user: uid 0 (root, ") +
         (none ? "without capabilities)" : "with its capabilities)");
}

}  // namespace

const char* sandboxModeName(SandboxMode mode) {
  switch (mode) {
    case SandboxMode::Require:
      return "require";
    case SandboxMode::Auto:
      return "auto";
    case SandboxMode::Off:
      break;
  }
  return "off";
}

SandboxMode parseSandboxMode(const std::string& name) {
  for (SandboxMode mode : {SandboxMode::Require, SandboxMode::Auto, SandboxMode::Off})
    if (name == sandboxModeName(mode)) return mode;
  throw PathwayError("unknown sandbox mode '" + name + "' (require, auto or off)");
}

std::string SandboxState::summary() const {
  std::string text = std::string("sandbox ") + sandboxModeName(mode);
  if (mode == SandboxMode::Off) return text + ": student code ran unconfined";
  for (size_t i = 0; i < inForce.size(); ++i) text += (i ? "; " : ": ") + inForce[i];
  if (!missing.empty()) {
    text += "; missing:";
    for (size_t i = 0; i < missing.size(); ++i) text += (i ? "; " : " ") + missing[i];
  }
  return text;
}

std::vector<std::string> systemReadablePaths() {
  return {"/usr",
          "/lib",
          "/lib64",
          "/bin",
          "/sbin",
          "/etc/ld.so.cache",
          "/etc/ld.so.conf",
          "/etc/ld.so.conf.d",
          "/dev/zero",
          "/dev/urandom",
          "/sys/devices/system/cpu",
          "/proc/self"};
}

namespace {

// Whether every user may reach `path`: each folder on the way searchable by others, the path
// itself readable (and searchable, if a folder). A missing path is reachable (nothing to read).
bool othersCanReach(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return true;
  const bool folder = S_ISDIR(info.st_mode);
  if (!(info.st_mode & S_IROTH) || (folder && !(info.st_mode & S_IXOTH))) return false;
  for (std::string up = path; up.size() > 1;) {
    const size_t slash = up.find_last_of('/');
    up = slash == 0 || slash == std::string::npos ? "/" : up.substr(0, slash);
    if (::stat(up.c_str(), &info) != 0 || !(info.st_mode & S_IXOTH)) return false;
    if (up == "/") break;
  }
  return true;
}

}  // namespace

std::string sandboxTemporaryRoot() {
  std::error_code error;
  const std::string system = std::filesystem::temp_directory_path(error).string();
  return !error && othersCanReach(system) ? system : "/tmp";
}

SandboxUser sandboxUser() {
  SandboxUser user;
  if (::geteuid() != 0) return user;
  user.changes = true;
  const passwd* nobody = ::getpwnam("nobody");
  user.uid = nobody ? nobody->pw_uid : 65534;
  user.gid = nobody ? nobody->pw_gid : 65534;
  return user;
}

void shareWithSandboxUser(const std::string& folder, SandboxMode mode) {
  const SandboxUser user = sandboxUser();
  if (mode == SandboxMode::Off || !user.changes) return;
  if (::chown(folder.c_str(), user.uid, user.gid) != 0)
    throw PathwayError(folder +
                       ": cannot hand it to the sandbox's user nobody: " + std::strerror(errno));
}

SandboxState probeSandbox(const SandboxPolicy& policy, SandboxMode mode) {
  const bool startsPrograms = policy.startsPrograms;
  SandboxState state;
  state.mode = mode;
  if (mode == SandboxMode::Off) return state;
  const int abi = landlock::abi();
  const bool seccomp = seccompAvailable();
  const std::string landlockName = "Landlock ABI " + std::to_string(abi);
  if (abi >= 1)
    state.inForce.push_back("files: " + landlockName + " (reads what its work needs, writes " +
                            "only its own folder)");
  else
    state.missing.push_back(
        "files: no Landlock in this kernel (5.13 or newer, with landlock in its LSM list)");
  if (abi >= 4 || seccomp)
    state.inForce.push_back(
        std::string("network: ") +
        (seccomp ? "seccomp kills on a network socket, refuses a local one" : "") +
        (abi >= 4 && seccomp ? ", " : "") + (abi >= 4 ? landlockName + " refuses TCP" : ""));
  else
    state.missing.push_back("network: neither seccomp nor Landlock ABI 4 in this kernel");
  if (!startsPrograms) {
    if (seccomp)
      state.inForce.push_back(
          "processes: seccomp forbids fork, exec and every clone but a "
          "thread's; no ptrace");
    else
      state.missing.push_back("processes: no seccomp in this kernel");
  }
  if (abi >= 6)
    state.inForce.push_back("signals: " + landlockName + " scopes them (and abstract sockets)");
  const std::string limits = limitsText(policy);
  state.inForce.push_back("no new privileges" + (limits.empty() ? "" : "; limits: " + limits));
  if (seccomp)
    state.inForce.push_back(
        startsPrograms
            ? "other processes: no System V IPC or message queue; no limit, priority or "
              "scheduling change but its own"
            : "other processes: no System V IPC or message queue; no signal, limit, priority or "
              "scheduling change but its own; not dumpable");
  else
    state.missing.push_back("other processes: no seccomp in this kernel");
  const SandboxUser user = sandboxUser();
  if (user.changes && !uidMapped(user.uid) && mode == SandboxMode::Require)
    throw PathwayError("--sandbox require runs student code as uid " + std::to_string(user.uid) +
                       ", which this system does not have (a user namespace that maps root "
                       "alone); grade where that user can be had, or with --sandbox auto");
  state.inForce.push_back(user.changes ? "user: uid " + std::to_string(user.uid) + " (not root)"
                                       : "user: uid " + std::to_string(::getuid()) +
                                             " (the grader's own, not root)");
  const bool required = abi >= 1 && (abi >= 4 || seccomp) && (startsPrograms || seccomp);
  if (mode == SandboxMode::Require && !required) {
    std::string what;
    for (const std::string& line : state.missing) what += (what.empty() ? "" : "; ") + line;
    throw PathwayError("--sandbox require: this machine cannot shut student code in (" + what +
                       "); grade on a newer kernel, or with --sandbox auto to take what it has");
  }
  return state;
}

SandboxState enterSandbox(const SandboxPolicy& policy, SandboxMode mode) {
  const SandboxState probed = probeSandbox(policy, mode);
  if (mode == SandboxMode::Off) return probed;
#ifndef __SANITIZE_ADDRESS__
  setLimit(RLIMIT_AS, policy.addressSpaceBytes);
#endif
  setLimit(RLIMIT_CPU, policy.cpuSeconds);
  setLimit(RLIMIT_NOFILE, policy.openFiles);
  setLimit(RLIMIT_FSIZE, policy.fileBytes);
  const rlimit noCores{0, 0};
  ::setrlimit(RLIMIT_CORE, &noCores);
  SandboxState state = probed;
  const SandboxUser user = sandboxUser();
  // Root can have an IPC namespace of its own as well, for nothing: System V objects and POSIX
  // message queues made in it (seccomp refuses them anyway) would end with the process.
  if (user.changes && ::unshare(CLONE_NEWIPC) == 0)
    for (std::string& line : state.inForce)
      if (line.rfind("other processes: ", 0) == 0) line += "; an IPC namespace of its own";
  if (user.changes) {
    int deathSignal = 0;  // a change of user clears it: it is set again after
    ::prctl(PR_GET_PDEATHSIG, &deathSignal, 0, 0, 0);
    const pid_t parent = ::getppid();
    const bool changed = ::setgroups(0, nullptr) == 0 &&
                         ::setresgid(user.gid, user.gid, user.gid) == 0 &&
                         ::setresuid(user.uid, user.uid, user.uid) == 0;
    if (!changed) {
      const std::string why = std::strerror(errno);
      if (mode == SandboxMode::Require)
        throw PathwayError("--sandbox require runs student code as uid " +
                           std::to_string(user.uid) + ", which this system refused (" + why +
                           "); grade where that user can be had, or with --sandbox auto");
      // Root without capabilities still owns root's files: only Landlock keeps it from them.
      if (landlock::abi() < 1)
        throw PathwayError("sandbox: could not become uid " + std::to_string(user.uid) + " (" +
                           why + "), and without Landlock root's files would be open to " +
                           "student code: grade as another user, or on a newer kernel");
      dropEveryCapability();
      state.missing.push_back("user: could not become uid " + std::to_string(user.uid) + " (" +
                              why + "): stays root, with every capability dropped");
    }
    if (deathSignal != 0) {
      ::prctl(PR_SET_PDEATHSIG, deathSignal, 0, 0, 0);
      if (::getppid() != parent) std::_Exit(1);  // the parent is gone already
    }
  }
  // What is in force, read back from the process itself: its real user.
  for (std::string& line : state.inForce)
    if (line.rfind("user: ", 0) == 0) line = actualUser();
  // Not dumpable: another process of the same user can neither trace it nor read its /proc.
  ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
    throw PathwayError(std::string("sandbox: no_new_privs refused: ") + std::strerror(errno));
  const int abi = landlock::abi();
  if (abi >= 1) applyLandlock(policy, abi);
  if (seccompAvailable()) applySeccomp(policy);
  return state;
}

}  // namespace pathway
