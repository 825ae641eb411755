//! The `player` interface (code 1): the server itself. Device list, driver names, subscription,
//! data modes, replace rules.

use super::common::U32Value;
use crate::wire::{DevAddr, Opaque, PlayerString};

/// `PLAYER_MAX_DEVICES`: devices in one device list.
pub const MAX_DEVICES: u32 = 4096;
/// `PLAYER_MAX_DRIVER_STRING_LEN`: driver name bytes, NUL included.
pub const MAX_DRIVER_NAME: u32 = 64;
/// `PLAYER_KEYLEN`: authentication key bytes.
pub const MAX_AUTH_KEY: u32 = 32;
/// Host name bytes in a name-service request.
pub const MAX_NAMESERVICE_NAME: u32 = 64;

/// `PLAYER_OPEN_MODE`: subscribe.
pub const OPEN_MODE: u8 = 1;
/// `PLAYER_CLOSE_MODE`: unsubscribe.
pub const CLOSE_MODE: u8 = 2;
/// `PLAYER_ERROR_MODE`: only in replies — access not granted.
pub const ERROR_MODE: u8 = 3;

/// `PLAYER_DATAMODE_PUSH`: the server default; data is sent as soon as it is published.
pub const DATAMODE_PUSH: u8 = 1;
/// `PLAYER_DATAMODE_PULL`: data waits in the server's queue until a data request.
pub const DATAMODE_PULL: u8 = 2;

/// Replace-rule actions.
pub const REPLACE_RULE_ACCEPT: i32 = 0;
pub const REPLACE_RULE_REPLACE: i32 = 1;
pub const REPLACE_RULE_IGNORE: i32 = 2;

/// Subtypes of bodiless `player` requests, and of SYNCH messages.
pub const REQ_DEVLIST: u8 = 1;
pub const REQ_DRIVERINFO: u8 = 2;
pub const REQ_DEV: u8 = 3;
pub const REQ_DATA: u8 = 4;
pub const REQ_DATAMODE: u8 = 5;
pub const REQ_AUTH: u8 = 7;
pub const REQ_NAMESERVICE: u8 = 8;
pub const REQ_ADD_REPLACE_RULE: u8 = 10;
pub const SYNCH_OK: u8 = 1;
pub const SYNCH_OVERFLOW: u8 = 2;

xdr_struct! {
    /// `player_device_devlist_t`: the devices served on the connection's port.
    pub struct DevList {
        pub devices: Vec<DevAddr> [max MAX_DEVICES],
    }
}

xdr_struct! {
    /// `player_device_driverinfo_t`: asked with `addr` set and an empty name; answered with the
    /// driver's name (`"stage"`, `"sicklms200"`).
    pub struct DriverInfo {
        pub addr: DevAddr,
        pub driver_name: PlayerString [max MAX_DRIVER_NAME],
    }
}

xdr_struct! {
    /// `player_device_req_t`: subscribe (access 1) or unsubscribe (2). The reply carries the
    /// access actually granted — 3 (error) can come back in an ACK, so always check it.
    pub struct DeviceReq {
        pub addr: DevAddr,
        pub access: u8,
        pub driver_name: PlayerString [max MAX_DRIVER_NAME],
    }
}

xdr_struct! {
    /// `player_device_datamode_req_t`: 1 = PUSH, 2 = PULL.
    pub struct DataModeReq {
        pub mode: u8,
    }
}

xdr_struct! {
    /// `player_device_auth_req_t` (not implemented by the TCP server: always NACKed).
    pub struct AuthReq {
        #[cfg_attr(any(test, feature = "proptest"), proptest(strategy = "proptest::strategy::Strategy::prop_map(proptest::collection::vec(proptest::arbitrary::any::<u8>(), 0..=32), Opaque::from)"))]
        pub auth_key: Opaque [max MAX_AUTH_KEY],
    }
}

xdr_struct! {
    /// `player_device_nameservice_req_t` (not implemented by the TCP server: always NACKed).
    pub struct NameServiceReq {
        pub name: PlayerString [max MAX_NAMESERVICE_NAME],
        pub port: u16,
    }
}

xdr_struct! {
    /// `player_add_replace_rule_req_t`: how the server queues this connection's outgoing
    /// messages. Each of the four filters is -1 for "any".
    pub struct AddReplaceRuleReq {
        pub interf: i32,
        pub index: i32,
        pub msg_type: i32,
        pub subtype: i32,
        pub replace: i32,
    }
}

interface_messages! {
    /// Messages of the `player` interface. The data request (subtype 4) and SYNCH/OK have no
    /// body and so no variant: they travel as `Body::Empty`.
    pub enum Player for PLAYER {
        Request 1 as REQ_DEVLIST => DevList(DevList),
        Request 2 as REQ_DRIVERINFO => DriverInfo(DriverInfo),
        Request 3 as REQ_DEV => Device(DeviceReq),
        Request 5 as REQ_DATAMODE => DataMode(DataModeReq),
        Request 7 as REQ_AUTH => Auth(AuthReq),
        Request 8 as REQ_NAMESERVICE => NameService(NameServiceReq),
        Request 10 as REQ_ADD_REPLACE_RULE => AddReplaceRule(AddReplaceRuleReq),
        Synch 2 as SYNCH_OVERFLOW => SynchOverflow(U32Value),
    }
}
