//! Declarative macros that turn a field list into a Player XDR struct, and a message table into
//! an interface's message enum. Each interface module is then little more than the protocol
//! document's tables, written as Rust.

/// Declares a struct whose wire form is its fields' encodings in declaration order, exactly as
/// Player's generator serialises a C struct.
///
/// A field written `pub x: T [max N]` is one of Player's few bounded arrays (`T x[N]` with a
/// count): its XDR length is checked against `N` before anything is decoded or allocated.
macro_rules! xdr_struct {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $( $(#[$field_meta:meta])* pub $field:ident : $ty:ty $([max $max:expr])? ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq, Default)]
        #[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub struct $name {
            $( $(#[$field_meta])* pub $field: $ty, )*
        }

        impl $crate::wire::xdr::Xdr for $name {
            const MIN_WIRE_SIZE: usize = 0 $( + <$ty as $crate::wire::xdr::Xdr>::MIN_WIRE_SIZE )*;

            // Inlined into the interface's decoder (`MessageSet::decode_message`), so that the
            // fields go straight into the message being built instead of through a copy of
            // the struct per layer.
            #[allow(unused_variables)]
            #[inline(always)]
            fn decode<'a>(
                input: &'a [u8],
                body: &::bytes::Bytes,
            ) -> $crate::wire::xdr::XdrResult<'a, Self> {
                $(
                    $(
                        $crate::wire::xdr::check_max_length(input, $max)
                            .map_err(|e| $crate::wire::xdr::in_field(e, stringify!($name), stringify!($field)))?;
                    )?
                    let (input, $field) = <$ty as $crate::wire::xdr::Xdr>::decode(input, body)
                        .map_err(|e| $crate::wire::xdr::in_field(e, stringify!($name), stringify!($field)))?;
                )*
                Ok((input, Self { $( $field, )* }))
            }

            #[allow(unused_variables)]
            fn encode<B: ::bytes::BufMut>(&self, out: &mut B) {
                $( $crate::wire::xdr::Xdr::encode(&self.$field, out); )*
            }

            fn encoded_len(&self) -> usize {
                0 $( + $crate::wire::xdr::Xdr::encoded_len(&self.$field) )*
            }
        }

        impl $crate::wire::xdr::XdrElement for $name {}

        ::paste::paste! {
            #[doc = concat!("[`", stringify!($name), "`] read in place from a received body, \
                each field the view of its own (see [`XdrView`](crate::wire::XdrView)).")]
            #[derive(Debug, Clone, Copy)]
            #[allow(missing_docs)]
            pub struct [<$name View>]<'a> {
                $( pub $field: $crate::wire::View<'a, $ty>, )*
                #[doc(hidden)]
                pub _body: ::core::marker::PhantomData<&'a [u8]>,
            }

            impl $crate::wire::XdrView for $name {
                type View<'a> = [<$name View>]<'a>;
                const FIXED_SIZE: Option<usize> = $crate::wire::xdr_view::fixed_sum(&[
                    $( <$ty as $crate::wire::XdrView>::FIXED_SIZE, )*
                ]);

                // The same checks, in the same order, as `decode` above.
                #[allow(unused_variables)]
                #[inline(always)]
                fn view(
                    input: &[u8],
                ) -> $crate::wire::xdr::XdrResult<'_, [<$name View>]<'_>> {
                    $(
                        $(
                            $crate::wire::xdr::check_max_length(input, $max)
                                .map_err(|e| $crate::wire::xdr::in_field(e, stringify!($name), stringify!($field)))?;
                        )?
                        let (input, $field) = <$ty as $crate::wire::XdrView>::view(input)
                            .map_err(|e| $crate::wire::xdr::in_field(e, stringify!($name), stringify!($field)))?;
                    )*
                    Ok((input, [<$name View>] { $( $field, )* _body: ::core::marker::PhantomData }))
                }

                #[allow(unused_variables)]
                fn to_owned_value(view: [<$name View>]<'_>) -> Self {
                    Self {
                        $( $field: <$ty as $crate::wire::XdrView>::to_owned_value(view.$field), )*
                    }
                }
            }
        }
    };
}

/// Declares an interface's messages: one enum variant per (class, subtype) with its body type.
///
/// ```ignore
/// interface_messages! {
///     pub enum Laser for LASER {
///         Data 1 as DATA_SCAN => Scan(LaserScan),
///         Request 1 as REQ_GET_GEOM => Geometry(LaserGeometry),
///     }
/// }
/// ```
/// A request's ACK (and a NACK that has a body) is encoded with the request's own structure,
/// so one `Request` entry covers REQ, ACK and NACK; the header tells them apart.
///
/// A row written `=> Variant(Type, boxed)` holds its body in a `Box` (see `stored!`); only
/// code that builds or destructures the enum itself sees the difference.
///
/// With `for CODE` each row also names its subtype (`as DATA_SCAN`, Player's name without the
/// `PLAYER_<INTERFACE>_` prefix): the macro then generates a typed
/// [`BodyKind`](crate::body_kind::BodyKind) constant per row (`Laser::DATA_SCAN`), the
/// interface's [`InterfaceMessages`](crate::interfaces::kind::InterfaceMessages) list, and
/// [`DataBody`](crate::body_kind::DataBody) for every DATA body. The enum's name must
/// be its [`Body`](crate::message::Body) variant's (in both forms: the decoder builds the
/// whole [`Message`](crate::message::Message) in place, body variant included). Without `for`
/// (the universal requests, valid on every interface) only the enum and its codec are made.
macro_rules! interface_messages {
    (
        $(#[$meta:meta])*
        pub enum $name:ident for $code:ident {
            $( $(#[$variant_meta:meta])* $class:ident $subtype:literal as $konst:ident => $variant:ident($ty:ty $(, $boxed:ident)?), )*
        }
    ) => {
        interface_messages! {
            $(#[$meta])*
            pub enum $name {
                $( $(#[$variant_meta])* $class $subtype => $variant($ty $(, $boxed)?), )*
            }
        }

        impl $name {
            $(
                #[doc = concat!("`PLAYER_", stringify!($code), "_", stringify!($konst), "`: ", stringify!($class), " subtype ", stringify!($subtype), ", body [`", stringify!($ty), "`].")]
                pub const $konst: $crate::body_kind::BodyKind<$ty> = {
                    fn peek(body: &$crate::message::Body) -> Option<&$ty> {
                        match body {
                            $crate::message::Body::$name($name::$variant(value)) => {
                                Some(::core::borrow::Borrow::borrow(value))
                            }
                            _ => None,
                        }
                    }
                    fn wrap(value: $ty) -> $crate::message::Body {
                        $crate::message::Body::$name($name::$variant(value.into()))
                    }
                    $crate::body_kind::BodyKind::new(
                        $crate::interfaces::kind::MessageKind {
                            interf: $crate::wire::Interface::$code,
                            class: $crate::wire::MessageClass::$class,
                            subtype: $subtype,
                        },
                        peek,
                        wrap,
                    )
                };
            )*
        }

        impl $crate::interfaces::kind::InterfaceMessages for $name {
            const INTERFACE: $crate::wire::Interface = $crate::wire::Interface::$code;
            const KINDS: &'static [$crate::interfaces::kind::MessageKind] =
                &[ $( $name::$konst.kind(), )* ];
        }

        $( data_body!($class, $name, $konst, $ty); )*
    };
    (
        $(#[$meta:meta])*
        pub enum $name:ident {
            $( $(#[$variant_meta:meta])* $class:ident $subtype:literal => $variant:ident($ty:ty $(, $boxed:ident)?), )*
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq)]
        #[cfg_attr(any(test, feature = "proptest"), derive(proptest_derive::Arbitrary))]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        pub enum $name {
            $( $(#[$variant_meta])* $variant(stored!($ty $(, $boxed)?)), )*
        }

        impl $crate::message::MessageSet for $name {
            fn decode_message(
                header: $crate::wire::Header,
                body: ::bytes::Bytes,
            ) -> Result<$crate::message::Message, $crate::message::DecodeError> {
                let class = header.msg_type.class();
                $(
                    if class == $crate::wire::MessageClass::$class && header.subtype == $subtype {
                        let (value, trailing) = match $crate::wire::xdr::decode_all::<$ty>(&body) {
                            Ok(decoded) => decoded,
                            Err(err) => {
                                return Err($crate::message::DecodeError::from_xdr(
                                    header, &body, err,
                                ));
                            }
                        };
                        // `body` is let go before the message is built, so that nothing (a drop
                        // call) stands between building it and returning it: built in place.
                        let trailing =
                            $crate::message::Message::trailing_of(&header, body, trailing);
                        return Ok($crate::message::Message {
                            header,
                            body: $crate::message::Body::$name(Self::$variant(value.into())),
                            trailing,
                        });
                    }
                )*
                Ok($crate::message::Message::unknown(header, body))
            }

            fn view_agrees(
                header: &$crate::wire::Header,
                body: &::bytes::Bytes,
            ) -> Result<(), $crate::view_disagreement::ViewDisagreement> {
                use $crate::wire::{Xdr, XdrView};
                let class = header.msg_type.class();
                let error = |e| $crate::message::DecodeError::from_xdr(*header, body, e).to_string();
                $(
                    if class == $crate::wire::MessageClass::$class && header.subtype == $subtype {
                        let encoded = |value: $ty| {
                            let mut out = Vec::new();
                            value.encode(&mut out);
                            out
                        };
                        let decoded = $crate::wire::xdr::decode_all::<$ty>(body)
                            .map(|(value, _)| encoded(value))
                            .map_err(error);
                        let viewed = $crate::wire::xdr_view::view_all::<$ty>(body)
                            .map(|view| encoded(<$ty as XdrView>::to_owned_value(view)))
                            .map_err(error);
                        return match decoded == viewed {
                            true => Ok(()),
                            false => Err($crate::view_disagreement::ViewDisagreement {
                                decoded: format!("{decoded:?}"),
                                viewed: format!("{viewed:?}"),
                            }),
                        };
                    }
                )*
                Ok(())
            }

            fn class(&self) -> $crate::wire::MessageClass {
                match self { $( Self::$variant(_) => $crate::wire::MessageClass::$class, )* }
            }

            fn subtype(&self) -> u8 {
                match self { $( Self::$variant(_) => $subtype, )* }
            }

            fn encode<B: ::bytes::BufMut>(&self, out: &mut B) {
                match self {
                    $(
                        Self::$variant(v) => $crate::wire::xdr::Xdr::encode(
                            ::core::borrow::Borrow::<$ty>::borrow(v),
                            out,
                        ),
                    )*
                }
            }

            fn encoded_len(&self) -> usize {
                match self {
                    $(
                        Self::$variant(v) => $crate::wire::xdr::Xdr::encoded_len(
                            ::core::borrow::Borrow::<$ty>::borrow(v),
                        ),
                    )*
                }
            }
        }
    };
}

/// The type an interface enum's variant holds: its body type, or a `Box` of it for a row marked
/// `boxed`.
///
/// A few bodies are far larger than the rest (a ranger's stamped readings carry a whole
/// geometry and configuration: 208 bytes, where a laser scan takes 80). Held inline they would
/// make every [`Body`](crate::message::Body) and [`Message`](crate::message::Message) that
/// size, and every message is built and moved on its way from the socket to its reader (a
/// 181-beam laser scan decoded measurably faster with `Message` at 192 bytes than at 280);
/// boxed, they cost one allocation on the rare message that carries them. The row's
/// [`BodyKind`](crate::body_kind::BodyKind) and `DataBody` still name the body type
/// itself, so readers never see the box.
macro_rules! stored {
    ($ty:ty) => { $ty };
    ($ty:ty, boxed) => { ::std::boxed::Box<$ty> };
}

/// `DataBody` for a DATA row of an interface table; nothing for the other classes, whose
/// structures are shared between rows (a get and a set request).
macro_rules! data_body {
    (Data, $name:ident, $konst:ident, $ty:ty) => {
        impl $crate::body_kind::DataBody for $ty {
            const KIND: $crate::body_kind::BodyKind<$ty> = $name::$konst;
        }
    };
    ($class:ident, $name:ident, $konst:ident, $ty:ty) => {};
}
