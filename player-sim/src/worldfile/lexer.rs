//! Tokens of Stage world files and Player config files (one syntax): words, numbers, strings,
//! `(`, `)`, `[`, `]`, and `#` comments to the end of the line. Every token knows its line and
//! column.

use super::WorldFileError;

#[derive(Debug, Clone, PartialEq)]
pub enum Token {
    Word(String),
    Number(f64),
    Str(String),
    Open,
    Close,
    ListOpen,
    ListClose,
}

/// A token and where it starts (1-based).
#[derive(Debug, Clone, PartialEq)]
pub struct Located {
    pub token: Token,
    pub line: usize,
    pub col: usize,
}

pub fn tokenize(text: &str, file: &str) -> Result<Vec<Located>, WorldFileError> {
    let mut tokens = Vec::new();
    let mut chars = text.char_indices().peekable();
    let (mut line, mut line_start) = (1usize, 0usize);
    while let Some(&(at, c)) = chars.peek() {
        let col = at - line_start + 1;
        let here = |token| Located { token, line, col };
        match c {
            '\n' => {
                chars.next();
                line += 1;
                line_start = at + 1;
            }
            c if c.is_whitespace() => {
                chars.next();
            }
            '#' => {
                while chars.peek().is_some_and(|&(_, c)| c != '\n') {
                    chars.next();
                }
            }
            '(' | ')' | '[' | ']' => {
                chars.next();
                tokens.push(here(match c {
                    '(' => Token::Open,
                    ')' => Token::Close,
                    '[' => Token::ListOpen,
                    _ => Token::ListClose,
                }));
            }
            '"' => {
                chars.next();
                let mut value = String::new();
                loop {
                    match chars.next() {
                        Some((_, '"')) => break,
                        Some((_, '\n')) | None => {
                            return Err(WorldFileError::at(
                                file,
                                line,
                                col,
                                "string not closed before the end of the line",
                            ));
                        }
                        Some((_, c)) => value.push(c),
                    }
                }
                tokens.push(here(Token::Str(value)));
            }
            _ => {
                let mut word = String::new();
                while let Some(&(_, c)) = chars.peek() {
                    if c.is_whitespace() || "()[]\"#".contains(c) {
                        break;
                    }
                    word.push(c);
                    chars.next();
                }
                // `point[0]`: an index written onto a name, as Stage's `block` points are.
                if word.starts_with(|c: char| c.is_alphabetic() || c == '_')
                    && let Some(suffix) = index_suffix(&text[at + word.len()..])
                {
                    word.push_str(suffix);
                    for _ in 0..suffix.len() {
                        chars.next();
                    }
                }
                let starts_number = word
                    .starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == '+' || c == '.');
                let token = match word.parse::<f64>() {
                    Ok(n) if starts_number => Token::Number(n),
                    _ if starts_number => {
                        return Err(WorldFileError::at(
                            file,
                            line,
                            col,
                            format!("{word:?} is not a number"),
                        ));
                    }
                    _ => Token::Word(word),
                };
                tokens.push(here(token));
            }
        }
    }
    Ok(tokens)
}

/// `[digits]` at the very start of `rest` (no space before it), if there.
fn index_suffix(rest: &str) -> Option<&str> {
    let inner = rest.strip_prefix('[')?;
    let digits = inner.bytes().take_while(u8::is_ascii_digit).count();
    (digits > 0 && inner[digits..].starts_with(']')).then(|| &rest[..digits + 2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_carry_positions() {
        let tokens = tokenize("size [ 12 -0.5 ]  # comment\nname \"rink\"\n", "w").unwrap();
        let kinds: Vec<&Token> = tokens.iter().map(|t| &t.token).collect();
        assert_eq!(
            kinds,
            [
                &Token::Word("size".into()),
                &Token::ListOpen,
                &Token::Number(12.0),
                &Token::Number(-0.5),
                &Token::ListClose,
                &Token::Word("name".into()),
                &Token::Str("rink".into()),
            ]
        );
        assert_eq!((tokens[5].line, tokens[5].col), (2, 1));
        assert_eq!((tokens[6].line, tokens[6].col), (2, 6));
    }

    #[test]
    fn indexed_names_are_one_word() {
        let tokens = tokenize("point[12] [ 1 2 ] size [3]", "w").unwrap();
        let kinds: Vec<&Token> = tokens.iter().map(|t| &t.token).collect();
        assert_eq!(kinds[0], &Token::Word("point[12]".into()));
        assert_eq!(kinds[1], &Token::ListOpen);
        assert_eq!(kinds[5], &Token::Word("size".into()));
        assert_eq!(kinds[6], &Token::ListOpen, "a space keeps a list a list");
        assert_eq!(tokens[1].col, 11);
    }

    #[test]
    fn bad_tokens_say_where() {
        let err = tokenize("a 1\nname \"open", "x.world").unwrap_err();
        assert_eq!(
            err.to_string(),
            "x.world:2:6: string not closed before the end of the line"
        );
        assert!(
            tokenize("pose [ 1x ]", "w")
                .unwrap_err()
                .to_string()
                .starts_with("w:1:8:")
        );
    }
}
