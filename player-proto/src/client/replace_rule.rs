//! Typed replace rules: how the server queues this connection's outgoing messages
//! (`PLAYER_PLAYER_REQ_ADD_REPLACE_RULE`, protocol document §4.7).
//!
//! The server tries a connection's rules in the order they were added and the first match
//! decides; a rule with the same four filters as an earlier one only changes that rule's
//! action. The client keeps its own list with exactly these semantics, so that after a
//! reconnect it can replay the rules in their original order and the new server queue behaves
//! like the old one.

use crate::interfaces::player::{
    AddReplaceRuleReq, REPLACE_RULE_ACCEPT, REPLACE_RULE_IGNORE, REPLACE_RULE_REPLACE,
};
use crate::wire::{Interface, MsgType};

/// What the server does with a message a rule matches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReplaceAction {
    /// Queue it normally (subject to the 1024-message limit).
    Accept,
    /// Replace the newest queued message of the same address, type and subtype.
    Replace,
    /// Drop it silently.
    Ignore,
}

impl ReplaceAction {
    fn code(self) -> i32 {
        match self {
            ReplaceAction::Accept => REPLACE_RULE_ACCEPT,
            ReplaceAction::Replace => REPLACE_RULE_REPLACE,
            ReplaceAction::Ignore => REPLACE_RULE_IGNORE,
        }
    }
}

/// One replace rule. A filter left `None` matches anything (it travels as -1).
///
/// Beware a rule without a message type filter: it also matches ACK and NACK, and with
/// [`ReplaceAction::Ignore`] it would swallow every reply.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReplaceRule {
    pub interf: Option<Interface>,
    pub index: Option<u16>,
    pub msg_type: Option<MsgType>,
    pub subtype: Option<u8>,
    pub action: ReplaceAction,
}

impl ReplaceRule {
    /// A rule for DATA messages of every device.
    pub fn data(action: ReplaceAction) -> ReplaceRule {
        ReplaceRule {
            interf: None,
            index: None,
            msg_type: Some(MsgType::Data),
            subtype: None,
            action,
        }
    }

    /// The viewer default (`ClientOptions::replace_old_data`): newest DATA replaces older
    /// queued DATA of the same device and subtype.
    pub fn newest_data() -> ReplaceRule {
        ReplaceRule::data(ReplaceAction::Replace)
    }

    /// A rule for DATA messages of one device (`interf:index`).
    pub fn device_data(interf: Interface, index: u16, action: ReplaceAction) -> ReplaceRule {
        ReplaceRule {
            interf: Some(interf),
            index: Some(index),
            ..ReplaceRule::data(action)
        }
    }

    /// Narrows the rule to one message subtype.
    pub fn with_subtype(self, subtype: u8) -> ReplaceRule {
        ReplaceRule {
            subtype: Some(subtype),
            ..self
        }
    }

    fn filters(&self) -> (Option<Interface>, Option<u16>, Option<MsgType>, Option<u8>) {
        (self.interf, self.index, self.msg_type, self.subtype)
    }

    /// The request body as it travels.
    pub fn to_request(&self) -> AddReplaceRuleReq {
        AddReplaceRuleReq {
            interf: self.interf.map_or(-1, |i| i32::from(i.0)),
            index: self.index.map_or(-1, i32::from),
            msg_type: self.msg_type.map_or(-1, |t| i32::from(t.code())),
            subtype: self.subtype.map_or(-1, i32::from),
            replace: self.action.code(),
        }
    }
}

/// Adds `rule` to `rules` as the server does: a rule with the same filters as an existing one
/// only changes that rule's action (keeping its place), anything else goes last.
pub(crate) fn remember(rules: &mut Vec<ReplaceRule>, rule: ReplaceRule) {
    match rules.iter_mut().find(|r| r.filters() == rule.filters()) {
        Some(existing) => existing.action = rule.action,
        None => rules.push(rule),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wildcards_travel_as_minus_one() {
        let req = ReplaceRule::newest_data().to_request();
        assert_eq!(
            (
                req.interf,
                req.index,
                req.msg_type,
                req.subtype,
                req.replace
            ),
            (-1, -1, 1, -1, REPLACE_RULE_REPLACE)
        );
        let req = ReplaceRule::device_data(Interface::LASER, 2, ReplaceAction::Ignore)
            .with_subtype(1)
            .to_request();
        assert_eq!(
            (
                req.interf,
                req.index,
                req.msg_type,
                req.subtype,
                req.replace
            ),
            (6, 2, 1, 1, REPLACE_RULE_IGNORE)
        );
    }

    #[test]
    fn same_filters_change_the_action_in_place() {
        let mut rules = vec![ReplaceRule::newest_data()];
        let laser = ReplaceRule::device_data(Interface::LASER, 0, ReplaceAction::Ignore);
        remember(&mut rules, laser);
        remember(&mut rules, ReplaceRule::data(ReplaceAction::Accept));
        assert_eq!(rules.len(), 2);
        assert_eq!(rules[0].action, ReplaceAction::Accept);
        assert_eq!(rules[1], laser);
    }
}
