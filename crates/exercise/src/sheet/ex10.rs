pub fn exercise() -> Result<crate::model::Exercise, super::SheetError> { Ok(crate::model::Exercise { id: "10".into(), statement: crate::text::Text::same(""), parts: vec![] }) }
