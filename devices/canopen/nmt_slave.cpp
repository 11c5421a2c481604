#include "devices/canopen/nmt_slave.h"

namespace canopen {

namespace {
constexpr std::string_view kMaster = "the master";  // the sender named in the transition log
}

void NmtSlave::on_frame(const sim::CanFrame& frame) {
  if (frame.rtr) return;
  const bool dlc_ok = policy_.require_dlc_2 ? frame.dlc == 2 : frame.dlc >= 2;
  if (!dlc_ok) return;
  const std::uint8_t target = frame.data[1];
  if (target != 0 && target != status_.node_id) return;
  switch (frame.data[0]) {
    case 0x01: commands_.execute_nmt(NmtCommand::Start, kMaster); break;
    case 0x02:
      if (policy_.stop_supported) commands_.execute_nmt(NmtCommand::Stop, kMaster);
      break;
    case 0x80: commands_.execute_nmt(NmtCommand::EnterPreOperational, kMaster); break;
    case 0x81: commands_.execute_nmt(NmtCommand::ResetNode, kMaster); break;
    case 0x82: commands_.execute_nmt(NmtCommand::ResetCommunication, kMaster); break;
    default: break;  // unknown command specifiers are ignored
  }
}

}  // namespace canopen
