// A sandbox for code the grader does not trust: a student's stage files, while they compile and
// while the grader's child renders with them. A process shuts itself in before any untrusted code
// runs in it (loading a library runs its static initializers) and before it starts a thread
// (Landlock binds the calling thread and what it starts afterwards). It needs no privileges:
//   - files: Landlock (kernel 5.13+) lets it read only what the policy lists and write only in
//     the policy's folders; no other submission, no reference, no report, no home;
//   - network: Landlock's TCP rules (ABI 4+) and a seccomp filter that kills on a network
//     socket (a local UNIX one is refused: glibc asks for one on its own, to reach nscd);
//   - processes: a seccomp filter that forbids fork, exec and every clone but a thread's (where
//     the policy starts none), and Landlock's scopes (ABI 6+): no signal to a process outside,
//     no abstract UNIX socket; no ptrace, no new privileges. A forbidden system call kills the
//     process on the spot (SIGSYS): the attempt fails the case, it is not quietly refused;
//   - limits: address space, CPU time, open files, file size (setrlimit);
//   - other processes: no System V IPC or POSIX message queue (nothing that outlives a case or
//     crosses to another child; under root, an IPC namespace of its own besides), no signal, limit,
//     priority or scheduling change of any process but itself, and it is not dumpable (another
//     process of its user cannot read its memory);
//   - user: a process running as root becomes the unprivileged user `nobody` first (where that
//     cannot be done, auto keeps root but drops every capability and says so; require refuses).
// What a process reports (SandboxState) is read back after it shut itself in: its real user.
// `--sandbox require|auto|off` picks how strict: require refuses to run untrusted code where the
// kernel cannot give files, network and processes; auto takes what the kernel gives; off is for
// debugging.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pathway {

enum class SandboxMode { Require, Auto, Off };
// "require", "auto", "off"; the parse throws PathwayError naming the three.
const char* sandboxModeName(SandboxMode mode);
SandboxMode parseSandboxMode(const std::string& name);

struct SandboxPolicy {
  std::vector<std::string> readable;  // files, or folders with all below them (missing ones skip)
  std::vector<std::string> writable;  // folders to create, write and remove files in
  bool startsPrograms = false;        // a compiler does (cc1plus, as, ld); a render does not
  // Whether it may remove files in its writable folders (a compiler's temporary files). A render
  // may not: a file it wrote stays where the grader counts it (a file deleted while held open
  // would hide its bytes from the grader's quota).
  bool removesFiles = true;
  uint64_t addressSpaceBytes = 0;  // 0: no limit (likewise below)
  uint64_t cpuSeconds = 0;
  uint64_t openFiles = 0;
  uint64_t fileBytes = 0;
};

// What a sandbox holds, or would hold on this kernel: one line per protection.
struct SandboxState {
  SandboxMode mode = SandboxMode::Off;
  std::vector<std::string> inForce;  // "files: Landlock ABI 7 (read: 3 paths, write: 1 folder)"
  std::vector<std::string> missing;  // "processes: no seccomp in this kernel"
  // "sandbox require: files (Landlock ABI 7), ...; missing: ..." for reports and results.json.
  std::string summary() const;
};

// The system folders every sandboxed process may read: programs and libraries (/usr, /lib...),
// the loader's cache, the processor's description the thread pools read, and /dev/null.
std::vector<std::string> systemReadablePaths();

// What `enterSandbox` would put in force in this process, without changing anything. With
// SandboxMode::Require it throws PathwayError naming the missing kernel feature when files,
// network or (where the policy starts no programs) processes cannot be shut in, or when a root
// grader's sandbox user does not exist here (a user namespace that maps root alone). (The
// policy's limits and whether it starts programs matter here.)
SandboxState probeSandbox(const SandboxPolicy& policy, SandboxMode mode);

// Shuts this process in for good, and everything it starts afterwards. Call it before any thread
// starts. Throws PathwayError when a protection the probe promised cannot be put in force (with
// Require, before anything changes, when one is missing).
SandboxState enterSandbox(const SandboxPolicy& policy, SandboxMode mode);

// The user a root process becomes (`nobody`, or uid 65534 where the system has no such user);
// other processes keep their own. The grader stages what a sandboxed process must read into
// folders it shares with this user (sandboxTemporaryFolder), so nobody can always work.
struct SandboxUser {
  bool changes = false;  // this process runs as root and becomes nobody
  unsigned uid = 0, gid = 0;
};
SandboxUser sandboxUser();
// Hands `folder` to the sandbox user, so that a sandboxed process of a root grader can write in
// it; does nothing when the mode is Off or the grader is not root. Throws PathwayError naming the
// folder when it cannot.
void shareWithSandboxUser(const std::string& folder, SandboxMode mode);
// Where a grader makes the folders its sandboxed processes read and write: the system's temporary
// folder where others can reach it, else /tmp.
std::string sandboxTemporaryRoot();

}  // namespace pathway
