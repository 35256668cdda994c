#pragma once
struct Ray {};
