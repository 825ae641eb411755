//! The `power` interface (code 2): batteries and chargers.

pub const MASK_VOLTS: u32 = 1;
pub const MASK_WATTS: u32 = 2;
pub const MASK_JOULES: u32 = 4;
pub const MASK_PERCENT: u32 = 8;
pub const MASK_CHARGING: u32 = 16;

xdr_struct! {
    /// `player_power_data_t`; `valid` says which fields are filled (`MASK_*`).
    #[derive(Copy)]
    pub struct PowerData {
        pub valid: u32,
        pub volts: f32,
        pub percent: f32,
        pub joules: f32,
        /// Negative = consuming.
        pub watts: f32,
        /// 1 charging, -1 discharging into something, 0 neither.
        pub charging: i32,
    }
}

xdr_struct! {
    /// `player_power_chargepolicy_config_t`.
    #[derive(Copy)]
    pub struct PowerChargePolicy {
        pub enable_input: u8,
        pub enable_output: u8,
    }
}

interface_messages! {
    /// Messages of the `power` interface.
    pub enum Power for POWER {
        Data 1 as DATA_STATE => State(PowerData),
        Request 1 as REQ_SET_CHARGING_POLICY => SetChargingPolicy(PowerChargePolicy),
    }
}
