# placeholder: filled in as tests land
test:
	@echo "no tests yet"
