//! Requests every interface understands (subtypes 247–255): capabilities and properties.

use crate::wire::PlayerString;

xdr_struct! {
    /// `player_capabilities_req_t`: "do you handle this (type, subtype)?" — ACK yes, NACK no.
    pub struct CapabilitiesReq {
        pub msg_type: u32,
        pub subtype: u32,
    }
}

xdr_struct! {
    /// `player_intprop_req_t`.
    pub struct IntProp {
        pub key: PlayerString,
        pub value: i32,
    }
}

xdr_struct! {
    /// `player_dblprop_req_t`.
    pub struct DoubleProp {
        pub key: PlayerString,
        pub value: f64,
    }
}

xdr_struct! {
    /// `player_strprop_req_t`.
    pub struct StringProp {
        pub key: PlayerString,
        pub value: PlayerString,
    }
}

xdr_struct! {
    /// `player_boolprop_req_t`: the value is a C `char`, sign-extended to 4 bytes.
    pub struct BoolProp {
        pub key: PlayerString,
        pub value: i8,
    }
}

interface_messages! {
    /// Requests valid on any interface, addressed to the device's own interface code.
    pub enum Universal {
        Request 255 => Capabilities(CapabilitiesReq),
        Request 254 => GetIntProp(IntProp),
        Request 253 => SetIntProp(IntProp),
        Request 252 => GetDoubleProp(DoubleProp),
        Request 251 => SetDoubleProp(DoubleProp),
        Request 250 => GetStringProp(StringProp),
        Request 249 => SetStringProp(StringProp),
        Request 248 => GetBoolProp(BoolProp),
        Request 247 => SetBoolProp(BoolProp),
    }
}
