(define (domain d)
  (:predicates (p ?x)))
; café ÿ
