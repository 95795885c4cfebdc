#include "cases/bow_shock/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>

namespace granshock {

namespace {

volatile std::sig_atomic_t g_signal = 0;

// exit_at_interrupt's message, copied where the handler can write it without allocating.
char g_exit_message[1024];
volatile std::sig_atomic_t g_exit_length = -1;  // -1: set the flag; else: say and leave

void write_all(const char* text, std::size_t length) {
  while (length > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, length);
    if (n <= 0) return;
    text += n;
    length -= std::size_t(n);
  }
}

extern "C" void on_signal(int sig) {
  if (g_signal == 0) g_signal = sig;
  if (g_exit_length >= 0) {
    // Only async-signal-safe calls here (signal-safety(7)).
    write_all(g_exit_message, std::size_t(g_exit_length));
    ::_exit(128 + sig);
  }
}

void set_mask(int how) {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(how, &set, nullptr);
}

}  // namespace

void hold_interrupts() {
  set_mask(SIG_BLOCK);
}

void release_interrupts() {
  set_mask(SIG_UNBLOCK);
}

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  release_interrupts();
}

int interrupt_signal() {
  return int(g_signal);
}

void throw_if_interrupted() {
  if (const int sig = interrupt_signal(); sig != 0) throw Interrupted(sig);
}

ExitAtInterrupt::ExitAtInterrupt(const std::string& message) {
  const std::size_t length = std::min(message.size(), sizeof(g_exit_message) - 2);
  std::memcpy(g_exit_message, message.data(), length);
  g_exit_message[length] = '\n';
  // The message is complete before the handler can see it armed; armed before the flag is
  // read: a signal in between either finds the message or left the flag for the check.
  std::atomic_signal_fence(std::memory_order_seq_cst);
  g_exit_length = std::sig_atomic_t(length + 1);
  if (const int sig = interrupt_signal(); sig != 0) {
    write_all(g_exit_message, length + 1);
    ::_exit(128 + sig);
  }
}

ExitAtInterrupt::~ExitAtInterrupt() {
  g_exit_length = -1;
}

}  // namespace granshock
